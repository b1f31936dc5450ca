#pragma once
// The playground's script and stylesheet, embedded from playground.js and playground.css at
// build time (playground_assets.cpp.in), so the page is one offline file.
#include <string_view>

namespace camcov::reports::playground {

std::string_view playgroundScript();
std::string_view playgroundStyle();

}  // namespace camcov::reports::playground
