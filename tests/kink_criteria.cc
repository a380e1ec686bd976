// Requirement: the three kink criteria give the angles of doc/benchmarks.md
// Case 10 on exact K data within 1e-4 degrees (the issue asks for 0.1
// degrees): the maximum hoop stress in closed form and its stationarity
// K_I sin + K_II (3 cos - 1) = 0, the maximum of Hussain, Pu and
// Underwood's G(theta), the relative minimum of Sih's S(theta) nearest the
// hoop-stress angle in plane strain and plane stress; the equivalent K of
// the hoop stress; the signs (K_II > 0 kinks to theta < 0, -K_II mirrors);
// and the small-K_II limit theta ~ -2 K_II / K_I.

#include <xcrack/fracture/kink_criteria.h>

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace xcrack;

std::ofstream logfile("output");

int
main()
{
  const double degree       = 180 / M_PI;
  const double nu           = 0.3;
  const double kappa_strain = 3 - 4 * nu, kappa_stress = (3 - nu) / (1 + nu);

  // KII/KI, then MTS, K_eq/K_I, G_max, S_min plane strain, plane stress.
  const double table[][6] = {
    {0.25, -25.3329, 1.08530, -27.5253, -24.1646, -23.3620},
    {0.5, -40.2078, 1.28279, -43.3825, -37.6272, -35.6516},
    {1, -53.1301, 1.78885, -57.3309, -51.9067, -49.0902},
    {2, -61.3418, 2.90054, -66.0717, -64.4301, -61.4345},
    {-0.5, 40.2078, 1.28279, 43.3825, 37.6272, 35.6516}};
  logfile << std::fixed << std::setprecision(4);
  double worst_angle = 0, worst_k = 0, worst_residual = 0;
  for (const auto &row : table)
    {
      const double k_I = 1, k_II = row[0];
      const double mts = KinkCriteria::max_hoop_stress_angle(k_I, k_II);
      const double g   = KinkCriteria::max_energy_release_rate_angle(k_I, k_II);
      const double s1 =
        KinkCriteria::min_strain_energy_density_angle(k_I, k_II, kappa_strain);
      const double s2 =
        KinkCriteria::min_strain_energy_density_angle(k_I, k_II, kappa_stress);
      logfile << "K_II/K_I = " << std::setw(5) << k_II << ": MTS "
              << std::setw(8) << mts * degree << ", G_max " << std::setw(8)
              << g * degree << ", S_min " << std::setw(8) << s1 * degree
              << " (plane strain) " << std::setw(8) << s2 * degree
              << " (plane stress)" << std::endl;
      for (const auto &[computed, reference] : {std::make_pair(mts, row[1]),
                                                std::make_pair(g, row[3]),
                                                std::make_pair(s1, row[4]),
                                                std::make_pair(s2, row[5])})
        worst_angle =
          std::max(worst_angle, std::abs(computed * degree - reference));
      worst_k =
        std::max(worst_k,
                 std::abs(KinkCriteria::hoop_stress_factor(mts, k_I, k_II) -
                          row[2]));
      worst_residual = std::max(worst_residual,
                                std::abs(k_I * std::sin(mts) +
                                         k_II * (3 * std::cos(mts) - 1)));
    }
  logfile << "largest angle difference to the table below 1e-4 degrees: "
          << (worst_angle < 1e-4 ? "yes" : "NO") << std::endl
          << "hoop-stress K_eq / K_I as tabulated (5e-6): "
          << (worst_k < 5e-6 ? "yes" : "NO") << std::endl
          << "stationarity residual of the hoop stress below 1e-12: "
          << (worst_residual < 1e-12 ? "yes" : "NO") << std::endl;

  // Pure mode II.
  const double mts = KinkCriteria::max_hoop_stress_angle(0, 1);
  logfile << "pure mode II: MTS " << mts * degree
          << " (-acos(1/3) = " << -std::acos(1. / 3) * degree << "), K_eq/K_II "
          << std::setprecision(6) << KinkCriteria::hoop_stress_factor(mts, 0, 1)
          << std::setprecision(4) << ", G_max "
          << KinkCriteria::max_energy_release_rate_angle(0, 1) * degree
          << ", S_min "
          << KinkCriteria::min_strain_energy_density_angle(0, 1, kappa_strain) *
               degree
          << " (acos((kappa - 1)/6) = "
          << -std::acos((kappa_strain - 1) / 6) * degree << ")" << std::endl;

  // Pure mode I and the small-K_II limit.
  logfile << "pure mode I: "
          << KinkCriteria::max_hoop_stress_angle(1, 0) * degree << ", "
          << KinkCriteria::max_energy_release_rate_angle(1, 0) * degree << ", "
          << KinkCriteria::min_strain_energy_density_angle(1, 0, kappa_strain) *
               degree
          << std::endl
          << "K_II/K_I = 0.01: -2 K_II/K_I = " << -0.02 * degree << ", MTS "
          << KinkCriteria::max_hoop_stress_angle(1, 0.01) * degree << ", S_min "
          << KinkCriteria::min_strain_energy_density_angle(1,
                                                           0.01,
                                                           kappa_strain) *
               degree
          << ", G_max "
          << KinkCriteria::max_energy_release_rate_angle(1, 0.01) * degree
          << std::endl;
}
