#pragma once
// Text helpers shared by the SVG and the HTML writers: escaping, fixed-precision numbers,
// relative URLs, and a width estimate for laying out labels without a font engine.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "util/escape_xml.h"

namespace camcov::reports {

using camcov::escapeXml;  // util/escape_xml.h: also the sweep debugger's (viz/)

// A pixel coordinate with one decimal: enough for screens and print, and byte-stable.
std::string px(double value);
// A number with `decimals` digits after the point, "—" when not finite (no pair of cameras).
std::string fixed(double value, int decimals);

// The items with `separator` between them.
std::string join(const std::vector<std::string>& items, std::string_view separator);

// Approximate width in px of `text` at `fontSize` px in a common sans-serif face. Layout only:
// it decides margins and whether labels must slant, so erring wide is safe.
double textWidth(std::string_view text, double fontSize);

// An id attribute value from a prefix and a name: "ts-dynamic9"; other bytes become '_'.
std::string anchorId(std::string_view prefix, std::string_view name);

// Text for inside a <script> element (JSON or JavaScript), for whatever data it holds: "</"
// becomes "<\/", and the "<" of "<!--" and of "<script" (any case) becomes "\u003C". Each means
// the same in a string, a regular expression or JSON, and none can end the element early or put
// the HTML parser into the script's escaped state, where "<!--<script>" in a description would
// keep the element open past its end and leave the page empty.
std::string scriptSafe(std::string_view text);

// `file` relative to `fromDir`, with '/' separators and every byte outside the URL-safe set
// percent-encoded: a relative URL for src and href attributes.
std::string relativeUrl(const std::filesystem::path& file, const std::filesystem::path& fromDir);

}  // namespace camcov::reports
