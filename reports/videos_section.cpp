// Section 7: the videos in videos/ next to the results (`camcov bench --videos` writes the
// median-seed run of each method per scene; `camcov video` may add others), embedded by
// relative URL so the report and its folder can move together.
#include <fmt/format.h>

#include <filesystem>

#include "reports/markup.h"
#include "reports/sections.h"

namespace camcov::reports {

std::string videosSection(const ReportData& data) {
  if (data.videos.empty()) return {};
  std::string out =
      "<section id=\"videos\">\n<h2>Videos</h2>\n<p>The MP4 files found in "
      "<code>videos/</code> next to the results, named <i>scene-method-seed</i>. By default "
      "<code>camcov bench</code> makes one per scene and method, of the seed whose average "
      "coverage is the median, so each shows a typical run (<code>--videos "
      "none|median|best|all</code>). They play from the folder, so keep it beside this "
      "file.</p>\n<div class=\"videos\">\n";
  for (const auto& url : data.videos) {
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
