#pragma once
// Output formats are chosen by file extension, case-insensitively.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace camcov::viz {

inline std::string lowercaseExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace camcov::viz
