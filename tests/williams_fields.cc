// Requirement: the Williams crack-tip fields reproduce the test values of
// doc/benchmarks.md Case 1 (displacements, stresses, Dirichlet data at the
// corners of [-1,1]^2) to the printed digits; their analytic gradient
// matches finite differences and, through Hooke's law, the stress formulas;
// the lips are traction free; a rotated and shifted tip frame gives the same
// field in its own coordinates.

#include <deal.II/base/mpi.h>

#include <deal.II/lac/vector.h>

#include <xcrack/fracture/williams.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

WilliamsField
field(const double k_I,
      const double k_II,
      const bool   plane_strain,
      const double nu = 0.3)
{
  WilliamsField f;
  f.k_I   = k_I;
  f.k_II  = k_II;
  f.mu    = 1 / (2 * (1 + nu));
  f.kappa = plane_strain ? 3 - 4 * nu : (3 - nu) / (1 + nu);
  return f;
}

const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     deg = numbers::PI / 180;

  // Displacement table (E = 1, nu = 0.3): plane, mode, r, theta, u1, u2.
  double max_error = 0;
  for (const auto &[strain, mode, r, theta, u1, u2] :
       std::vector<std::tuple<bool, int, double, double, double, double>>{
         {true, 1, 1, 0, 0.41489997, 0},
         {true, 1, 1, 90, 0.66010181, 0.66010181},
         {true, 1, 1, 180, 0, 1.45214990},
         {true, 1, 1, -135, 0.49758343, -1.20127267},
         {true, 1, 0.25, 45, 0.26182825, 0.10845281},
         {true, 2, 1, 0, 0, -0.41489997},
         {true, 2, 1, 90, 1.39354827, 0.07334465},
         {true, 2, 1, 180, 1.45214990, 0},
         {true, 2, 1, -135, -1.48195048, 0.18003274},
         {false, 1, 1, 90, 0.76165594, 0.76165594},
         {false, 1, 1, -135, 0.55254413, -1.33395953},
         {false, 2, 1, 90, 1.49510240, -0.02820948},
         {false, 2, 0.25, 45, 0.47474125, -0.18783277}})
    {
      const auto u =
        field(mode == 1, mode == 2, strain).displacement(r, theta * deg);
      max_error =
        std::max({max_error, std::abs(u[0] - u1), std::abs(u[1] - u2)});
    }
  logfile << "displacement table (13 values): all within 1e-8: "
          << yes(max_error < 1e-8) << std::endl;

  max_error = 0;
  for (const auto &[mode, theta, s11, s22, s12] :
       std::vector<std::tuple<int, double, double, double, double>>{
         {1, 0, 0.39894228, 0.39894228, 0},
         {1, 45, 0.23826381, 0.49888541, 0.05397650},
         {1, 90, 0.14104740, 0.42314219, -0.14104740},
         {1, 135, 0.20664510, 0.09869210, -0.13031080},
         {2, 45, -0.35931370, 0.05397650, 0.23826381},
         {2, 90, -0.42314219, -0.14104740, 0.14104740}})
    {
      const auto s = field(mode == 1, mode == 2, true).stress(1, theta * deg);
      max_error    = std::max({max_error,
                               std::abs(s[0][0] - s11),
                               std::abs(s[1][1] - s22),
                               std::abs(s[0][1] - s12)});
    }
  logfile << "stress table (6 angles): all within 1e-8: "
          << yes(max_error < 1e-8) << std::endl;

  // Corners of [-1,1]^2, tip at the origin, crack along x < 0.
  const WilliamsSolution<2> mode_I(field(1, 0, true),
                                   Point<2>(),
                                   Tensor<1, 2>({1, 0}),
                                   Tensor<1, 2>({0, 1}));
  const WilliamsSolution<2> mode_II(field(0, 1, true),
                                    Point<2>(),
                                    Tensor<1, 2>({1, 0}),
                                    Tensor<1, 2>({0, 1}));
  Vector<double>            u(2);
  max_error = 0;
  for (const auto &[solution, x, y, u1, u2] : std::vector<
         std::
           tuple<const WilliamsSolution<2> *, double, double, double, double>>{
         {&mode_I, 1, 1, 0.6227360308, 0.2579457097},
         {&mode_I, -1, 1, 0.5917297563, 1.4285620029},
         {&mode_I, -1, -1, 0.5917297563, -1.4285620029},
         {&mode_I, -1, 1e-300, 0, 1.4521499007},
         {&mode_II, 1, 1, 1.0637716819, -0.2889519842},
         {&mode_II, -1, 1, 1.7623460495, 0.2140962158}})
    {
      solution->vector_value(Point<2>(x, y), u);
      max_error =
        std::max({max_error, std::abs(u[0] - u1), std::abs(u[1] - u2)});
    }
  logfile << "Dirichlet data at the corners (6 values): all within 1e-9: "
          << yes(max_error < 1e-9) << std::endl;

  // Gradient: finite differences and Hooke's law, mixed mode with mode III,
  // random points, in a rotated and shifted 3D frame.
  WilliamsField mixed       = field(1.3, -0.7, true);
  mixed.k_III               = 0.4;
  const double       nu     = 0.3;
  const double       lambda = mixed.mu * (3 - mixed.kappa) / (mixed.kappa - 1);
  const Tensor<1, 3> e1({0.6, 0.8, 0}), e2({-0.8 * 0.6, 0.6 * 0.6, 0.8});
  const WilliamsSolution<3> rotated(mixed, Point<3>(0.3, -0.2, 0.5), e1, e2);
  std::mt19937              rng(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  double fd_error = 0, hooke_error = 0, frame_error = 0;
  for (unsigned int i = 0; i < 200; ++i)
    {
      const double r = 0.05 + std::abs(uniform(rng)), theta = 3 * uniform(rng);
      // Hooke's law in the local frame.
      const Tensor<2, 3>          grad  = mixed.displacement_gradient(r, theta);
      const SymmetricTensor<2, 3> eps   = symmetrize(grad);
      const double                tr    = eps[0][0] + eps[1][1];
      const SymmetricTensor<2, 3> sigma = mixed.stress(r, theta);
      hooke_error                       = std::max(
        {hooke_error,
                               std::abs(lambda * tr + 2 * mixed.mu * eps[0][0] - sigma[0][0]),
                               std::abs(lambda * tr + 2 * mixed.mu * eps[1][1] - sigma[1][1]),
                               std::abs(2 * mixed.mu * eps[0][1] - sigma[0][1]),
                               std::abs(2 * mixed.mu * eps[0][2] - sigma[0][2]),
                               std::abs(2 * mixed.mu * eps[1][2] - sigma[1][2])});

      // The same point in global coordinates.
      const Point<3> p = Point<3>(0.3, -0.2, 0.5) + r * std::cos(theta) * e1 +
                         r * std::sin(theta) * e2 +
                         uniform(rng) * cross_product_3d(e1, e2);
      Vector<double> value(3);
      rotated.vector_value(p, value);
      const Tensor<1, 3> local = mixed.displacement(r, theta);
      const Tensor<1, 3> e3    = cross_product_3d(e1, e2);
      for (unsigned int d = 0; d < 3; ++d)
        frame_error =
          std::max(frame_error,
                   std::abs(value[d] - (local[0] * e1[d] + local[1] * e2[d] +
                                        local[2] * e3[d])));

      std::vector<Tensor<1, 3>> gradients(3);
      rotated.vector_gradient(p, gradients);
      const double h = 1e-6;
      for (unsigned int j = 0; j < 3; ++j)
        {
          Point<3> plus = p, minus = p;
          plus[j] += h;
          minus[j] -= h;
          Vector<double> up(3), um(3);
          rotated.vector_value(plus, up);
          rotated.vector_value(minus, um);
          for (unsigned int c = 0; c < 3; ++c)
            fd_error =
              std::max(fd_error,
                       std::abs((up[c] - um[c]) / (2 * h) - gradients[c][j]));
        }
    }
  logfile << "gradient vs central differences (200 points): within 1e-7: "
          << yes(fd_error < 1e-7) << std::endl
          << "Hooke's law of the gradient vs stress formulas: within 1e-12: "
          << yes(hooke_error < 1e-12) << std::endl
          << "rotated 3D frame: u = R^T u_local within 1e-14: "
          << yes(frame_error < 1e-14) << std::endl;

  // Traction-free lips.
  double lip = 0;
  for (const double theta : {numbers::PI, -numbers::PI})
    {
      const auto s = mixed.stress(0.7, theta);
      lip          = std::max(
        {lip, std::abs(s[1][1]), std::abs(s[0][1]), std::abs(s[1][2])});
    }
  logfile << "lips traction free (s22 = s12 = s23 = 0 at theta = +-pi): "
          << yes(lip < 1e-15) << std::endl;
}
