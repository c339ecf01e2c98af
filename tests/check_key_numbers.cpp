// check_key_numbers REF.json RUN.json NAME
//
// Compares one key number of a chapter run with its reference entry.
// Reference entry (reference/<chapter>.json, "numbers" object):
//   "name": { "value": expected, "unit": "...",
//             "tolerance": {"rel": r} or {"abs": a},
//             "why_tolerance": "...", "source": "thesis section/figure/page or formula",
//             "thesis_value": value printed in the thesis (or null), "note": "..." }
// "value" is always an independent truth: the thesis number where our method
// reproduces it, otherwise an exact formula or an independent computation, with
// the thesis number kept in "thesis_value" and the gap explained in "note".
// Exit 0 when |ours - value| is within the tolerance, 1 otherwise.
#include <cmath>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: check_key_numbers REF.json RUN.json NAME\n";
    return 2;
  }
  nlohmann::json ref, run;
  try {
    std::ifstream(argv[1]) >> ref;
    std::ifstream(argv[2]) >> run;
  } catch (const std::exception& e) {
    std::cerr << "cannot read JSON: " << e.what() << "\n";
    return 1;
  }
  const std::string name = argv[3];
  if (!ref["numbers"].contains(name)) {
    std::cerr << name << ": not in " << argv[1] << "\n";
    return 1;
  }
  if (!run.contains(name)) {
    std::cerr << name << ": the run did not write it to " << argv[2] << "\n";
    return 1;
  }
  const auto& r = ref["numbers"][name];
  const double expected = r.at("value").get<double>();
  const double ours = run[name].at("value").get<double>();
  const std::string unit = r.value("unit", "");
  if (run[name].value("unit", "") != unit) {
    std::cerr << name << ": unit '" << run[name].value("unit", "") << "' but reference says '"
              << unit << "'\n";
    return 1;
  }
  const auto& tol = r.at("tolerance");
  double allowed = 0.0;
  if (tol.contains("abs")) allowed = tol["abs"].get<double>();
  if (tol.contains("rel")) allowed = std::max(allowed, tol["rel"].get<double>() * std::fabs(expected));
  const double err = std::fabs(ours - expected);
  std::cout.precision(10);
  std::cout << name << ": ours " << ours << " " << unit << ", expected " << expected
            << ", |diff| " << err << " (allowed " << allowed << ")";
  if (r.contains("thesis_value") && !r["thesis_value"].is_null())
    std::cout << ", thesis " << r["thesis_value"];
  std::cout << "\n  source: " << r.value("source", "?") << "\n";
  if (!(err <= allowed)) {
    std::cout << "FAIL\n";
    return 1;
  }
  return 0;
}
