// Unit tests of lib/gearhb/app/cli (ParameterSet): on/off flags, former names.
#include <string>

#include <gtest/gtest.h>

#include "gearhb/app/cli.hpp"

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
