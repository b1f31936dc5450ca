// printable(): what a terminal would obey or garble becomes \xNN, every valid UTF-8 character
// stays. The byte sequences are the Unicode standard's own examples of well- and ill-formed
// UTF-8 (table 3-7 and section 3.9's examples), not output copied from the function.
#include "util/printable.h"

#include <gtest/gtest.h>

namespace camcov {
namespace {

TEST(Printable, KeepsPlainTextAndEveryValidUtf8Character) {
  EXPECT_EQ(printable("cameraFoV 30"), "cameraFoV 30");
  // θ (2 bytes), ± (2), … (3), U+10FFFF (4, the last code point), an emoji (4).
  const std::string valid = "\xce\xb8 \xc2\xb1 \xe2\x80\xa6 \xf4\x8f\xbf\xbf \xf0\x9f\x93\xb7";
  EXPECT_EQ(printable(valid), valid);
}

TEST(Printable, EscapesControlBytesIncludingDelAndTheC1Controls) {
  EXPECT_EQ(printable("a\x1b[31mb"), "a\\x1b[31mb");
  EXPECT_EQ(printable(std::string("nul\0", 4)), "nul\\x00");
  EXPECT_EQ(printable("\x7f"), "\\x7f");
  // U+009B, the one-byte CSI of the C1 set, is \xc2\x9b in UTF-8: both bytes escaped.
  EXPECT_EQ(printable("\xc2\x9b"), "\\xc2\\x9b");
  // U+00A0 (no-break space) is the first character after the C1 set: kept.
  EXPECT_EQ(printable("\xc2\xa0"), "\xc2\xa0");
}

TEST(Printable, EscapesEveryIllFormedSequenceByteByByte) {
  EXPECT_EQ(printable("\x80"), "\\x80");                             // a continuation byte alone
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");                    // overlong '/', C0 never leads
  EXPECT_EQ(printable("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");           // overlong, three bytes
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // a surrogate (U+D800)
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // beyond U+10FFFF
  EXPECT_EQ(printable("\xe2\x80"), "\\xe2\\x80");                    // truncated at the end
  EXPECT_EQ(printable("\xe2\x80x"), "\\xe2\\x80x");                  // truncated before ASCII
  EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
}

TEST(Printable, LinesAreKeptOnlyWhenAskedAndTheCutCountsCharacters) {
  EXPECT_EQ(printable("a\nb\tc"), "a\\x0ab\\x09c");
  EXPECT_EQ(printable("a\nb\tc", {.keepLines = true}), "a\nb\tc");
  EXPECT_EQ(printable("\xce\xb8\xce\xb8\xce\xb8", {.maxCharacters = 2}), "\xce\xb8\xce\xb8…");
  EXPECT_EQ(printable("abc", {.maxCharacters = 3}), "abc");
  EXPECT_EQ(printable("", {.maxCharacters = 0}), "");
}

}  // namespace
}  // namespace camcov
