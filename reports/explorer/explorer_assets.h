#pragma once
// The explorer's script and stylesheet, embedded from explorer.js and explorer.css at build
// time (explorer_assets.cpp.in), so the page is one offline file.
#include <string_view>

namespace camcov::reports::explorer {

std::string_view explorerScript();
std::string_view explorerStyle();
// Zoom and pan of the world, and small objects drawn enlarged: the explorer's and the
// playground's (world_view.js), embedded before each page's own script.
std::string_view worldViewScript();

}  // namespace camcov::reports::explorer
