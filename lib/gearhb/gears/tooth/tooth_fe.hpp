#pragma once
// Euler-Bernoulli beam finite elements for the tooth model of thesis ch. 7.
//
// Each tooth is a cantilever beam from the root circle to the tip. A beam
// element of length L and bending stiffness EI, with degrees of freedom
// [w1, theta1, w2, theta2] (transverse displacement y and rotation about x at
// its two nodes), has the classical stiffness matrix (thesis §7.2; e.g.
// Przemieniecki, Theory of Matrix Structural Analysis, §5.3)
//
//               EI  [ 12    6L   -12    6L  ]
//     K^(e) =  ---- [ 6L   4L^2  -6L   2L^2 ]
//              L^3  [-12   -6L    12   -6L  ]
//                   [ 6L   2L^2  -6L   4L^2 ]
//
// Its shape functions are the cubic Hermite polynomials, which contain the
// exact solution of EI w'''' = 0 between nodes: for point forces and moments
// applied at nodes the element is exact (nodal values equal the elastic line)
// even when EI changes from element to element (a stepped beam).
//
// BeamModel assembles any number of beams, each with any number of elements,
// into one global system K Q = F + R (thesis: 4 beams x 11 nodes = 88 DOFs),
// global node numbers running beam after beam (thesis nodes 1-11, 12-22, ...;
// here 0-based). DOF 2n is w of node n, DOF 2n+1 its rotation.
//
// Constraints:
//   clamp(n)            w = 0, theta = 0
//   guide(n, w0)        theta = 0, w = w0 imposed (the thesis' "guided" root
//                       moving by the static transmission error)
//   fuse(m, s, sign)    node s follows node m: w_s = sign * w_m and (if asked)
//                       theta_s = theta_m. The thesis (§7.2) fuses the contact
//                       nodes of two facing teeth with sign = -1 (the second
//                       tooth's frame is turned by 180 deg) and equal rotations.
//
// How the constraints are imposed: by a constraint transformation
// Q = T u + Q0 (u: the independent unknowns, Q0: imposed values), solving
// (T' K T) u = T' (F - K Q0) with Eigen's LDLT. The thesis' "Boolean matrix"
// (§7.2, the 86 -> 82 reduction) is exactly this T for its fused nodes, with the
// imposed DOFs moved to the right-hand side as [K(:,1) K(:,45)] X_STE. Reactions
// are R = K Q - F (nonzero at constrained DOFs; at a fused pair the slave and
// master entries carry the equal and opposite contact force and moment).
#include <vector>

#include <Eigen/Dense>

namespace gearhb {

// 4x4 element stiffness (formula above). EI [N m^2], L [m].
Eigen::Matrix4d beam_element_stiffness(double EI, double L);

class BeamModel {
 public:
  // A beam with nodes at axial positions x (strictly increasing, x[0] = 0 at
  // its root) and one bending stiffness EI per element (x.size() - 1 values).
  // Returns the beam index.
  int add_beam(const std::vector<double>& x, const std::vector<double>& EI);

  int beams() const { return int(beams_.size()); }
  int nodes() const { return n_nodes_; }
  int dofs() const { return 2 * n_nodes_; }
  int node(int beam, int local) const;           // global node of a beam's local node
  int beam_nodes(int beam) const { return int(beams_.at(beam).x.size()); }
  const std::vector<double>& beam_x(int beam) const { return beams_.at(beam).x; }
  static int w_dof(int node) { return 2 * node; }
  static int theta_dof(int node) { return 2 * node + 1; }

  Eigen::MatrixXd stiffness() const;             // assembled K (dofs x dofs)

  void clamp(int node);
  void guide(int node, double w0);
  void fuse(int master, int slave, double w_sign, bool fuse_rotation);
  void add_force(int node, double Fy);
  void add_moment(int node, double Mx);

  struct Solution {
    Eigen::VectorXd Q;          // all nodal displacements
    Eigen::VectorXd reactions;  // R = K Q - F
  };
  // Throws std::runtime_error if the constrained system is singular (a mechanism:
  // a beam not held anywhere), naming the node and beam that can move freely.
  Solution solve() const;

  // Nodal forces a beam's elements exert, K_beam q_beam (2 per node, local order):
  // for element e, [V1, M1, V2, M2] = K^(e) q^(e) are the forces and moments the
  // nodes apply on the element.
  Eigen::Vector4d element_end_forces(const Solution& s, int beam, int element) const;

 private:
  struct Beam {
    std::vector<double> x, EI;
    int first_node = 0;
  };
  enum class Kind { free, prescribed, slave };
  struct DofState {
    Kind kind = Kind::free;
    double value = 0.0;   // prescribed value
    int master = -1;      // slave: master DOF
    double factor = 1.0;  // slave: Q_s = factor * Q_master
  };
  void prescribe(int dof, double value);
  void check_held(const Eigen::LDLT<Eigen::MatrixXd>& ldlt, const Eigen::MatrixXd& Kr,
                  const std::vector<int>& column) const;
  void make_slave(int dof, int master_dof, double factor);
  std::vector<Beam> beams_;
  int n_nodes_ = 0;
  std::vector<DofState> state_;
  std::vector<double> force_;
};

// Closed-form deflections used to check the FE (exact formulas).
//
// Cantilever clamped at x = 0, point force F at x = a; elastic line
// (thesis §7.4; e.g. Roark's Formulas for Stress and Strain, table 8.1 case 1a):
//     y(x) = F x^2 (3a - x) / (6 EI)   for x <= a,
//     y(x) = F a^2 (3x - a) / (6 EI)   for x >  a.
double cantilever_point_load_deflection(double F, double a, double x, double EI);

// Stepped cantilever (EI_e constant on [x_e, x_e+1]), unit force at x = a:
// deflection at a by the unit-load method, delta = int_0^a (a - x)^2 / EI(x) dx
//     = sum_e [(a - x_e)^3 - (a - min(x_e+1, a))^3] / (3 EI_e).
double stepped_cantilever_compliance(const std::vector<double>& x, const std::vector<double>& EI,
                                     double a);

// Beam of length L guided at x = 0 (rotation fixed, transverse displacement X
// imposed) and clamped at x = L, EI(x) piecewise constant on the segments of x.
// With end shear V and moment M(x) = M0 - V x, zero end rotation gives
// M0 = V I1 / I0, and the displacement is X = V (I2 - I1^2 / I0), where
// I_k = int_0^L x^k / EI(x) dx. Returns the stiffness V / X. For constant EI:
// 12 EI / L^3 (Roark table 8.1 case 1e).
double stepped_clamped_guided_stiffness(const std::vector<double>& x, const std::vector<double>& EI);

}  // namespace gearhb
