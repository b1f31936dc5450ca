#!/usr/bin/env bash
# Makes scenes/real/ from the recorded tracks in ../shared/tracks: three pedestrian
# scenes (the busiest 60 s of ETH univ, ETH hotel and UCY zara01) and both football plays whole.
# The recordings are not ours to copy into the repository, so the scenes are made from them
# here (scenes/real/ is not committed); the main job runs this first. Same tracks, same files.
#
#   scripts/make_real_scenes.sh [TRACKS_DIR] [CAMCOV]
#
# The camera teams (scenes/README.md says why):
#   pedestrians: 6 cameras at 1.5 m/s, turning at 1 rad/s, θ = 30°: ground robots at a brisk
#                walking pace, as many as the busiest minutes have people to watch in groups;
#   football:    8 cameras at 6 m/s, turning at 1.5 rad/s, θ = 25°, 1 m inside a 5 m run-off:
#                fast rail or drone cameras around the pitch, as many as a broadcast uses.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tracks=${1:-$repo/../shared/tracks}
camcov=${2:-$repo/build/src/cli/camcov}
[ -d "$tracks" ] || { echo "make_real_scenes.sh: no recorded tracks at $tracks" >&2; exit 2; }
[ -x "$camcov" ] || { echo "make_real_scenes.sh: build camcov first (scripts/build.sh)" >&2; exit 2; }
out=$repo/scenes/real
mkdir -p "$out"
people=(--busiest 60 --cameras 6 --camera-speed 1.5 --camera-turn 1 --fov 30)
football=(--cameras 8 --camera-speed 6 --camera-turn 1.5 --fov 25)
"$camcov" import ethucy "$tracks/pedestrians/eth_univ" --fps 15 "${people[@]}" -o "$out/eth_univ.json"
"$camcov" import ethucy "$tracks/pedestrians/eth_hotel" --fps 25 "${people[@]}" -o "$out/eth_hotel.json"
"$camcov" import ethucy "$tracks/pedestrians/ucy_zara01" --fps 25 "${people[@]}" -o "$out/ucy_zara01.json"
"$camcov" import lastrow "$tracks/football/liverpool_2-1_chelsea.csv" "${football[@]}" \
  -o "$out/football_liverpool_chelsea.json"
"$camcov" import lastrow "$tracks/football/real_madrid_vs_barcelona.csv" "${football[@]}" \
  -o "$out/football_real_madrid_barcelona.json"
