#pragma once
// The explorer's script and stylesheet, embedded from explorer.js and explorer.css at build
// time (explorer_assets.cpp.in), so the page is one offline file.
#include <string_view>

namespace camcov::reports::explorer {

std::string_view explorerScript();
std::string_view explorerStyle();

}  // namespace camcov::reports::explorer
