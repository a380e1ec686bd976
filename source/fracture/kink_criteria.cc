#include <xcrack/fracture/kink_criteria.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace xcrack
{
  namespace KinkCriteria
  {
    namespace
    {
      constexpr double pi = 3.14159265358979323846;

      /**
       * The interior extremum of @p f on (-pi, pi) (a minimum of f; pass -f
       * for a maximum) nearest @p guess: local minima of f on a grid of
       * 0.25 degrees, then golden-section search to round-off between the
       * neighbours of the chosen one. The faces theta = +-pi are excluded.
       */
      double
      extremum_near(const std::function<double(double)> &f, const double guess)
      {
        const unsigned int  n    = 1440;
        const double        step = 2 * pi / n;
        std::vector<double> theta(n - 1), value(n - 1);
        for (unsigned int i = 0; i + 1 < n; ++i)
          {
            theta[i] = -pi + (i + 1) * step;
            value[i] = f(theta[i]);
          }
        double best = guess, distance = std::numeric_limits<double>::max();
        bool   found = false;
        for (unsigned int i = 1; i + 1 < theta.size(); ++i)
          if (value[i] <= value[i - 1] && value[i] <= value[i + 1] &&
              std::abs(theta[i] - guess) < distance)
            {
              distance = std::abs(theta[i] - guess);
              best     = theta[i];
              found    = true;
            }
        if (!found)
          return guess;
        double       a = best - step, b = best + step;
        const double ratio = (std::sqrt(5.) - 1) / 2;
        double       c = b - ratio * (b - a), d = a + ratio * (b - a);
        double       fc = f(c), fd = f(d);
        while (b - a > 1e-13)
          {
            if (fc < fd)
              {
                b  = d;
                d  = c;
                fd = fc;
                c  = b - ratio * (b - a);
                fc = f(c);
              }
            else
              {
                a  = c;
                c  = d;
                fc = fd;
                d  = a + ratio * (b - a);
                fd = f(d);
              }
          }
        return (a + b) / 2;
      }
    } // namespace



    double
    max_hoop_stress_angle(const double k_I, const double k_II)
    {
      if (k_II == 0)
        return 0;
      return 2 * std::atan((k_I - std::sqrt(k_I * k_I + 8 * k_II * k_II)) /
                           (4 * k_II));
    }



    double
    hoop_stress_factor(const double theta, const double k_I, const double k_II)
    {
      const double c = std::cos(theta / 2);
      return c * (k_I * c * c - 1.5 * k_II * std::sin(theta));
    }



    double
    kinked_energy_release_rate(const double theta,
                               const double k_I,
                               const double k_II)
    {
      const double c = std::cos(theta), s = std::sin(theta), t = theta / pi;
      const double c2 = c * c;
      return 4 / ((3 + c2) * (3 + c2)) * std::pow((1 - t) / (1 + t), t) *
             ((1 + 3 * c2) * k_I * k_I - 8 * s * c * k_I * k_II +
              (9 - 5 * c2) * k_II * k_II);
    }



    double
    max_energy_release_rate_angle(const double k_I, const double k_II)
    {
      if (k_II == 0)
        return 0;
      return extremum_near(
        [&](const double theta) {
          return -kinked_energy_release_rate(theta, k_I, k_II);
        },
        max_hoop_stress_angle(k_I, k_II));
    }



    double
    strain_energy_density_factor(const double theta,
                                 const double k_I,
                                 const double k_II,
                                 const double kappa)
    {
      const double c = std::cos(theta), s = std::sin(theta);
      return (1 + c) * (kappa - c) * k_I * k_I +
             2 * s * (2 * c - (kappa - 1)) * k_I * k_II +
             ((kappa + 1) * (1 - c) + (1 + c) * (3 * c - 1)) * k_II * k_II;
    }



    double
    min_strain_energy_density_angle(const double k_I,
                                    const double k_II,
                                    const double kappa)
    {
      if (k_II == 0)
        return 0;
      return extremum_near(
        [&](const double theta) {
          return strain_energy_density_factor(theta, k_I, k_II, kappa);
        },
        max_hoop_stress_angle(k_I, k_II));
    }
  } // namespace KinkCriteria
} // namespace xcrack
