#include "kinematics/track_motion.h"

#include <algorithm>
#include <cmath>

namespace camcov::kinematics {

std::pair<std::size_t, double> TrackMotion::locate(double t) const {
  const auto& times = track_.times;
  if (times.size() == 1 || t <= times.front()) return {0, 0.0};
  if (t >= times.back()) return {times.size() - 2, 1.0};
  const auto next = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t k = static_cast<std::size_t>(next - times.begin()) - 1;
  return {k, (t - times[k]) / (times[k + 1] - times[k])};
}

geometry::Vec2 TrackMotion::positionAt(double t) const {
  const auto& p = track_.positions;
  if (p.size() == 1) return p.front();
  const auto [k, u] = locate(t);
  return geometry::lerp(p[k], p[k + 1], u);
}

double TrackMotion::headingAt(double t) const {
  const auto& h = track_.headings;
  if (h.empty()) return 0.0;
  if (h.size() == 1) return h.front();
  const auto [k, u] = locate(t);
  return h[k] + geometry::wrapAngle(h[k + 1] - h[k]) * u;
}

double TrackMotion::maxSpeed() const {
  double fastest = 0.0;
  for (std::size_t k = 0; k + 1 < track_.times.size(); ++k) {
    fastest = std::max(fastest, geometry::distance(track_.positions[k], track_.positions[k + 1]) /
                                    (track_.times[k + 1] - track_.times[k]));
  }
  return fastest;
}

double TrackMotion::maxTurnRate() const {
  double fastest = 0.0;
  const auto& h = track_.headings;
  for (std::size_t k = 0; k + 1 < h.size(); ++k) {
    fastest = std::max(fastest, std::abs(geometry::wrapAngle(h[k + 1] - h[k])) /
                                    (track_.times[k + 1] - track_.times[k]));
  }
  return fastest;
}

}  // namespace camcov::kinematics
