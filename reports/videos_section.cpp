// Section 7: the videos in videos/ next to the results (`camcov bench --videos` writes the
// median-seed run of each method per scene; `camcov video` may add others), embedded by
// relative URL so the report and its folder can move together.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "util/natural_order.h"

#include "control/methods.h"
#include "reports/markup.h"
#include "reports/method_style.h"
#include "reports/sections.h"

namespace camcov::reports {
namespace {

// A video named scene-method-seed, split at the batch's method whose name it holds; a name
// holding none keeps its whole stem as the scene and comes after the methods.
struct VideoName {
  std::string scene, seed;
  std::size_t methodRank;
};

VideoName videoName(const std::string& stem, const std::vector<std::string>& methods) {
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::string middle = "-" + methods[k] + "-";
    if (const auto at = stem.rfind(middle); at != std::string::npos)
      return {stem.substr(0, at), stem.substr(at + middle.size()), k};
  }
  return {stem, "", methods.size()};
}

// Per scene, the methods in the order of every other table and figure (paper, local, camcov,
// then others by name), then by seed.
std::vector<std::string> inMethodOrder(std::vector<std::string> urls,
                                       const std::vector<std::string>& batchMethods) {
  const std::vector<std::string> methods = control::inMethodOrder(batchMethods);
  std::stable_sort(urls.begin(), urls.end(), [&](const std::string& a, const std::string& b) {
    const VideoName x = videoName(std::filesystem::path(a).stem().string(), methods);
    const VideoName y = videoName(std::filesystem::path(b).stem().string(), methods);
    if (x.scene != y.scene) return naturalLess(x.scene, y.scene);
    if (x.methodRank != y.methodRank) return x.methodRank < y.methodRank;
    return naturalLess(x.seed, y.seed);
  });
  return urls;
}

}  // namespace

std::string videosSection(const ReportData& data) {
  if (data.videos.empty()) return {};
  std::string out =
      "<section id=\"videos\">\n<h2>Videos</h2>\n<p>The MP4 files found in "
      "<code>videos/</code> next to the results, named <i>scene-method-seed</i>. By default "
      "<code>camcov bench</code> makes one per scene and method, of the seed whose average "
      "coverage is the median, so each shows a typical run (<code>--videos "
      "none|median|best|all</code>). They play from the folder, so keep it beside this "
      "file.</p>\n<div class=\"videos\">\n";
  for (const auto& url : inMethodOrder(data.videos, data.manifest.methods)) {
    // The URL is percent-encoded; its file name without ".mp4" is the caption.
    const std::string name = std::filesystem::path(url).stem().string();
    out += fmt::format(
        "<figure class=\"video\"><video controls preload=\"metadata\" src=\"{}\"></video>"
        "<figcaption>{}</figcaption></figure>\n",
        escapeXml(url), escapeXml(name));
  }
  return out + "</div>\n</section>\n";
}

}  // namespace camcov::reports
