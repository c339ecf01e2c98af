// The mesh stiffnesses of a planetary set from its teeth (tools/planetary_stiffness.hpp), as
// gearhb_planetary reads them: the star set of examples/gtf_star_five_planets_teeth.json (the
// sun-planet pair by gearhb_gear's potential-energy model at 64 phases, the ring-planet pair
// by the internal potential-energy tooth, gamma_rs from the teeth), against reading the same
// set with rectangular waves (examples/gtf_star_five_planets.json). Times go to the report.
//   build/bin/gearhb_bench --benchmark_filter=planetary_read
#include <string>

#include <benchmark/benchmark.h>

#include "gearhb/tools/planetary_file.hpp"

using namespace gearhb;

static void BM_planetary_read(benchmark::State& state, const char* example) {
  const std::string path = std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_planetary/examples/" + example;
  for (auto _ : state) {
    const PlanetaryFile f = read_planetary_file(path, {});
    benchmark::DoNotOptimize(f.meshes.sun.mean);
  }
}
BENCHMARK_CAPTURE(BM_planetary_read, rectangular, "gtf_star_five_planets.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_planetary_read, tooth_model, "gtf_star_five_planets_teeth.json")->Unit(benchmark::kMillisecond);
