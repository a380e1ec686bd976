#ifndef xcrack_fracture_kink_criteria_h
#define xcrack_fracture_kink_criteria_h

namespace xcrack
{
  /**
   * The classical criteria for the direction in which a crack tip under
   * mixed-mode loading (K_I, K_II) kinks, as pure functions (doc/benchmarks.md
   * Case 10, whose conventions they follow: the angle theta is measured
   * from e1 towards e2, and K_II > 0 gives a kink theta_c < 0). The
   * direction criterion plugins wrap them; tests check them against the
   * closed forms.
   *
   * All three assume an open crack (K_I >= 0); callers pass max(K_I, 0).
   */
  namespace KinkCriteria
  {
    /**
     * Maximum tangential stress (Erdogan and Sih 1963): the root of
     * K_I sin(theta) + K_II (3 cos(theta) - 1) = 0 in closed form,
     * theta_c = 2 arctan[(K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)].
     */
    double
    max_hoop_stress_angle(const double k_I, const double k_II);

    /// The hoop stress factor sqrt(2 pi r) sigma_theta_theta at @p theta:
    /// cos(theta/2) [K_I cos^2(theta/2) - 3/2 K_II sin(theta)].
    double
    hoop_stress_factor(const double theta, const double k_I, const double k_II);

    /**
     * The energy release rate of a kinked extension in the direction
     * @p theta, times E' (Hussain, Pu and Underwood 1974, in the sign
     * convention of doc/benchmarks.md): 4 (3 + cos^2)^-2 ((1 - t)/(1 + t))^t
     * [(1 + 3 cos^2) K_I^2 - 8 sin cos K_I K_II + (9 - 5 cos^2) K_II^2],
     * t = theta / pi.
     */
    double
    kinked_energy_release_rate(const double theta,
                               const double k_I,
                               const double k_II);

    /// The direction that maximises kinked_energy_release_rate().
    double
    max_energy_release_rate_angle(const double k_I, const double k_II);

    /**
     * Sih's strain energy density factor S(theta), times 16 mu:
     * (1 + cos)(kappa - cos) K_I^2 + 2 sin (2 cos - kappa + 1) K_I K_II
     * + [(kappa + 1)(1 - cos) + (1 + cos)(3 cos - 1)] K_II^2.
     */
    double
    strain_energy_density_factor(const double theta,
                                 const double k_I,
                                 const double k_II,
                                 const double kappa);

    /// The relative minimum of S nearest the maximum-hoop-stress angle
    /// (Sih 1974), faces excluded.
    double
    min_strain_energy_density_angle(const double k_I,
                                    const double k_II,
                                    const double kappa);
  } // namespace KinkCriteria
} // namespace xcrack

#endif
