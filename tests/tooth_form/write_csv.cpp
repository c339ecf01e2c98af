// Writes the generated tooth forms of the issue-33 example gears as one CSV (a test aid,
// not a program of the project): gear,x_mm,y_mm,nx,ny,segment. figures/tooth_form.py
// draws it. Usage: tooth_form_csv OUT.csv
#include <cstdio>
#include <string>
#include <vector>

#include "gearhb/gears/geometry/tooth_form.hpp"
#include "example_gears.hpp"

using namespace gearhb;
using namespace tooth_form_examples;

namespace {
struct Case {
  std::string name;
  GearGeometry g;
  ToothFormOptions o;
};
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: tooth_form_csv OUT.csv\n");
    return 2;
  }
  std::vector<Case> cases;
  cases.push_back({"thesis z50 m3", thesis(), {}});
  cases.push_back({"FZG C z16 x0.1817", fzg16(), {}});
  cases.push_back({"FZG C z24 x0.1715", fzg24(), {}});
  cases.push_back({"z10 x0 (undercut)", pinion10(), {}});
  Case relieved{"z16 relief 0.1 mm + rounding 0.3 mm", fzg16(), {}};
  relieved.o.relief = tip_relief(relieved.g, 0.1e-3, ReliefStart::diameter, 2 * 39.5e-3, ReliefShape::linear);
  relieved.o.tip_rounding_radius = 0.3e-3;
  cases.push_back(relieved);
  std::FILE* f = std::fopen(argv[1], "w");
  if (!f) return 1;
  std::fprintf(f, "gear,x_mm,y_mm,nx,ny,segment\n");
  for (const Case& c : cases) {
    const ToothForm form = tooth_form(c.g, c.o);
    const FormPolyline s = form_sector(form, -1, 3);
    for (size_t i = 0; i < s.points.size(); ++i)
      std::fprintf(f, "%s,%.9g,%.9g,%.9g,%.9g,%s\n", c.name.c_str(), s.points[i].x() * 1e3, s.points[i].y() * 1e3,
                   s.normals[i].x(), s.normals[i].y(), tooth_segment_name(s.segment[i]));
  }
  return std::fclose(f) == 0 ? 0 : 1;
}
