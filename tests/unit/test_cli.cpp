// Unit tests of the application frame: lib/gearhb/app/cli (ParameterSet: on/off flags,
// former names), one_line (study.hpp) and the input-file reader (core/text_file.hpp).
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "gearhb/app/cli.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/core/text_file.hpp"

using namespace gearhb;

TEST(ParameterSet, FlagsTakeOneZeroTrueFalse) {
  bool flag = true;
  ParameterSet P;
  P.add("exact_contact", &flag, "-", "a flag");
  for (const auto& [text, value] : {std::pair<std::string, bool>{"0", false}, {"1", true}, {"false", false},
                                    {"true", true}, {"0.0", false}, {"1.0", true}}) {
    P.set("exact_contact=" + text);
    EXPECT_EQ(flag, value) << text;
  }
  EXPECT_EQ(P.to_json()["exact_contact"]["value"], true);   // echoed as a JSON boolean
  for (const std::string bad : {"2", "-1", "0.5", "yes", "on", ""}) {
    try {
      P.set("exact_contact=" + bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("exact_contact"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(flag);   // a refused value leaves the flag as it was
  EXPECT_NE(P.help_text().find("(flag: 1 or 0)"), std::string::npos);
}

TEST(ParameterSet, FormerNamesAreRefusedWithTheNewName) {
  double Fa = 0.01;
  ParameterSet P;
  P.add("Fa", &Fa, "N", "harmonic force amplitude");
  P.renamed("F", "Fa");
  try {
    P.set("F=0.02");
    ADD_FAILURE() << "accepted the former name";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "parameter 'F' was renamed to 'Fa'");
  }
  P.set("Fa=0.02");
  EXPECT_EQ(Fa, 0.02);
}

// --- one_line (app/study.hpp): every error line is one line of valid UTF-8 ----------
// Known values: RFC 3629 section 3 (the well-formed byte sequences) and its examples.
TEST(OneLine, KeepsWellFormedUtf8AndEscapesEverythingElse) {
  EXPECT_EQ(one_line("plain text"), "plain text");
  EXPECT_EQ(one_line("a\nb"), "a\\nb");                             // a newline of a --set value
  EXPECT_EQ(one_line("tab\there"), "tab\\x09here");                 // control character
  EXPECT_EQ(one_line("del\x7f"), "del\\x7f");
  EXPECT_EQ(one_line("caf\xc3\xa9"), "caf\xc3\xa9");                 // U+00E9, 2 bytes
  EXPECT_EQ(one_line("\xe2\x82\xac"), "\xe2\x82\xac");               // U+20AC, 3 bytes
  EXPECT_EQ(one_line("\xf0\x9f\x98\x80"), "\xf0\x9f\x98\x80");       // U+1F600, 4 bytes
  EXPECT_EQ(one_line("x\xffy"), "x\\xffy");                          // 0xff never occurs in UTF-8
  EXPECT_EQ(one_line("\x80"), "\\x80");                               // a lone continuation byte
  EXPECT_EQ(one_line("\xc0\xaf"), "\\xc0\\xaf");                      // overlong '/'
  EXPECT_EQ(one_line("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");             // overlong '/', 3 bytes
  EXPECT_EQ(one_line("\xed\xa0\x80"), "\\xed\\xa0\\x80");             // U+D800, a surrogate
  EXPECT_EQ(one_line("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");    // U+110000, beyond Unicode
  EXPECT_EQ(one_line("\xc3"), "\\xc3");                               // cut at the end
  EXPECT_EQ(one_line(std::string("a\0b", 3)), "a\\x00b");
}

// --- read_text_file (core/text_file.hpp): bounded, text only, errors in words -------
namespace {
std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = ::testing::TempDir() + "gearhb_text_file_" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  std::fwrite(content.data(), 1, content.size(), f);
  std::fclose(f);
  return path;
}
std::string text_file_error(const std::string& path) {
  try {
    read_text_lines(path);
  } catch (const TextFileError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(TextFile, RefusesWhatIsNotBoundedText) {
  EXPECT_EQ(text_file_error(temp_file("ok", "phase,gap\r\n0,1\n")), "");
  EXPECT_EQ(text_file_error(temp_file("nul", std::string("phase,gap\n0,1\n\0 garbage", 23))),
            "holds a NUL byte (byte 15): not a text file");
  EXPECT_EQ(text_file_error(temp_file("long", "a\n" + std::string(4097, 'x') + "\n")),
            "line 2 is longer than 4096 characters");
  EXPECT_EQ(text_file_error(temp_file("crlf_4096", std::string(4096, 'x') + "\r\n")), "");
  EXPECT_EQ(text_file_error("/proc/self/mem"), "cannot be read (Input/output error)");
  EXPECT_EQ(text_file_error("/dev/zero"), "is not a regular file (a device or a pipe?)");
  EXPECT_EQ(text_file_error("/"), "is a folder, not a file");
  EXPECT_EQ(text_file_error("/proc/self/pagemap"), "is larger than 16 MiB");   // 8 bytes per page of the address space
}
