// One model per thread (harmonic_balance.hpp, "Threads"): two threads, each building
// its own HarmonicBalance and sweeping NLvib example 03 with Floquet stability and
// bifurcations, reproduce the serial sweep bit for bit. Independent truth: the serial
// run of the same code (the property under test is that threads change nothing).
#include <thread>

#include <gtest/gtest.h>

#include "gearhb/hb/frequency_sweep.hpp"
#include "test_models.hpp"

using namespace gearhb;

namespace {
FrequencyCurve sweep_ex03() {
  const HarmonicBalance hb = test_models::nlvib_ex03(10);
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 0.8;
  o.direction = SweepDirection::down;
  return sweep_frequency(hb, o, "NLvib ex03 H=10");
}

void expect_identical(const FrequencyCurve& a, const FrequencyCurve& b) {
  ASSERT_EQ(a.branch.points.size(), b.branch.points.size());
  for (std::size_t i = 0; i < a.branch.points.size(); ++i) {
    ASSERT_EQ(a.branch.points[i].omega, b.branch.points[i].omega) << "point " << i;
    ASSERT_TRUE((a.branch.points[i].X.array() == b.branch.points[i].X.array()).all()) << "point " << i;
  }
  ASSERT_EQ(a.stable, b.stable);
  ASSERT_EQ(a.bifurcations.size(), b.bifurcations.size());
  for (std::size_t i = 0; i < a.bifurcations.size(); ++i) EXPECT_EQ(a.bifurcations[i].omega, b.bifurcations[i].omega);
}
}  // namespace

TEST(Threads, OneModelPerThreadReproducesTheSerialSweepBitForBit) {
  const FrequencyCurve serial = sweep_ex03();
  ASSERT_TRUE(serial.complete) << serial.failure;
  ASSERT_GT(serial.bifurcations.size(), 0u);
  FrequencyCurve first, second;
  std::thread a([&] { first = sweep_ex03(); });
  std::thread b([&] { second = sweep_ex03(); });
  a.join();
  b.join();
  expect_identical(serial, first);
  expect_identical(serial, second);
}
