#include <xcrack/level_set_update/hamilton_jacobi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    namespace HamiltonJacobi
    {
      namespace
      {
        /// The (constant) gradient of @p phi on the @p s th simplex.
        template <int dim>
        Tensor<1, dim>
        simplex_gradient(const SimplexBand<dim>    &band,
                         const std::vector<double> &phi,
                         const std::size_t          s)
        {
          Tensor<1, dim> g;
          for (unsigned int k = 0; k <= dim; ++k)
            g += phi[band.nodes(s)[k]] * band.gradients(s)[k];
          return g;
        }



        /// The mean of @p f over the nodes of the @p s th simplex.
        template <int dim>
        double
        simplex_mean(const SimplexBand<dim>    &band,
                     const std::vector<double> &f,
                     const std::size_t          s)
        {
          double sum = 0;
          for (const unsigned int i : band.nodes(s))
            sum += f[i];
          return sum / (dim + 1);
        }



        /**
         * One explicit step of phi_t + H = 0 by the simplex scheme, H = V .
         * grad phi - f linearised on each simplex: @p flux(s, grad phi on
         * s) gives the simplex's characteristic velocity V and its source
         * f, and H on the simplex follows from its constant gradient. A
         * simplex sends H to the nodes V points to (k_i = V . grad lambda_i
         * > 0), each with the weight of its volume times k_i / sum_j
         * max(k_j, 0) (Barth and Sethian's distribution), and a node moves
         * by @p dt times the weighted mean of what it receives:
         *
         * - from the simplices that hold its backward characteristic (it is
         *   their only downstream node), when it has any: its new value
         *   then depends on itself and its upstream nodes only, with
         *   non-negative weights (monotone, as Godunov's rule on a lattice);
         * - else from the simplices it is downstream of, the mean's
         *   denominator at least @p floor times its dual cell (sum |T| /
         *   (dim + 1)) (0: the plain mean, time-accurate for a linear
         *   phi). A node that barely lies downstream
         *   would otherwise take a whole simplex's residual, which
         *   oscillates and grows over the iterations of a steady-state
         *   phase (doc/verification/level-set-update.md).
         *
         * Nodes @p fixed stay.
         */
        template <int dim, typename Flux>
        void
        step(const SimplexBand<dim>  &band,
             const Flux              &flux,
             const double             dt,
             const double             floor,
             const std::vector<char> &fixed,
             std::vector<double>     &phi)
        {
          // Per node: H and weight from the simplices that hold its
          // characteristic; from the others it is downstream of; its dual cell.
          std::vector<std::array<double, 5>> sums(band.size(),
                                                  {{0, 0, 0, 0, 0}});
          for (std::size_t s = 0; s < band.n_simplices(); ++s)
            {
              const Tensor<1, dim> g        = simplex_gradient(band, phi, s);
              const auto [V, f]             = flux(s, g);
              const double                H = V * g - f;
              std::array<double, dim + 1> k;
              double                      K            = 0;
              unsigned int                n_downstream = 0;
              double                      norm         = 0;
              for (unsigned int j = 0; j <= dim; ++j)
                {
                  k[j] = V * band.gradients(s)[j];
                  norm += std::abs(k[j]);
                }
              // V along a face gives k_j = 0 up to round-off, which must not
              // decide whether the simplex holds a node's characteristic
              // (the result would jump with the partition's round-off).
              for (unsigned int j = 0; j <= dim; ++j)
                {
                  k[j] = (k[j] > 1e-9 * norm ? k[j] : 0.);
                  K += k[j];
                  n_downstream += (k[j] > 0);
                }
              for (unsigned int j = 0; j <= dim; ++j)
                {
                  auto &sum = sums[band.nodes(s)[j]];
                  sum[4] += band.volume(s) / (dim + 1);
                  if (k[j] == 0)
                    continue;
                  const unsigned int which = (n_downstream == 1 ? 0 : 2);
                  const double       w     = k[j] / K * band.volume(s);
                  sum[which] += w * H;
                  sum[which + 1] += w;
                }
            }
          for (std::size_t i = 0; i < band.size(); ++i)
            if (!fixed[i])
              {
                const auto &sum   = sums[i];
                double      delta = 0;
                if (sum[1] > 0)
                  delta = dt * sum[0] / sum[1];
                else if (sum[3] > 0)
                  delta = dt * sum[2] / std::max(sum[3], floor * sum[4]);
                phi[i] -= delta;
              }
        }



      } // namespace



      template <int dim>
      Tensor<1, dim>
      gradient(const SimplexBand<dim>    &band,
               const std::vector<double> &phi,
               const std::size_t          i)
      {
        Tensor<1, dim> g;
        double         volume = 0;
        for (const unsigned int s : band.simplices_of(i))
          {
            g += band.volume(s) * simplex_gradient(band, phi, s);
            volume += band.volume(s);
          }
        return volume > 0 ? g / volume : g;
      }



      template <int dim>
      void
      propagate(const SimplexBand<dim>    &band,
                const std::vector<double> &speed,
                std::vector<double>       &phi)
      {
        double fastest = 0;
        for (std::size_t i = 0; i < band.size(); ++i)
          if (band.is_active(i))
            fastest = std::max(fastest, std::abs(speed[i]));
        if (fastest == 0 || band.n_simplices() == 0)
          return;
        const unsigned int n_steps =
          std::max(1., std::ceil(fastest / (0.5 * band.min_height())));
        const std::vector<char> fixed(band.size(), 0);
        // H = F |grad phi| = V . grad phi, V = F grad phi / |grad phi|.
        const auto flux = [&](const std::size_t s, const Tensor<1, dim> &g) {
          const double F = simplex_mean(band, speed, s), norm = g.norm();
          return std::make_pair(norm > 0 ? Tensor<1, dim>(F / norm * g) :
                                           Tensor<1, dim>(),
                                0.);
        };
        for (unsigned int k = 0; k < n_steps; ++k)
          step(band, flux, 1. / n_steps, 0., fixed, phi);
      }



      template <int dim>
      unsigned int
      reinitialise(const SimplexBand<dim> &band,
                   std::vector<double>    &phi,
                   const double            width)
      {
        if (band.n_simplices() == 0)
          return 0;
        const double              h    = band.min_height();
        const std::vector<double> phi0 = phi;
        // The nodes of the simplices the zero set cuts: set once to their
        // distance to its linearisation there (the nearest over the cut
        // simplices), and kept.
        std::vector<char>   fixed(band.size(), 0);
        std::vector<double> steepest(band.size(), 0.);
        for (std::size_t s = 0; s < band.n_simplices(); ++s)
          {
            bool positive = false, other = false;
            for (const unsigned int i : band.nodes(s))
              (phi0[i] > 0 ? positive : other) = true;
            if (!(positive && other))
              continue;
            const double g = simplex_gradient(band, phi0, s).norm();
            for (const unsigned int i : band.nodes(s))
              {
                fixed[i]    = 1;
                steepest[i] = std::max(steepest[i], g);
              }
          }
        for (std::size_t i = 0; i < band.size(); ++i)
          if (fixed[i])
            phi[i] = (steepest[i] > 0 ? phi0[i] / steepest[i] : 0.);

        std::vector<double> sign(band.size(), 0.);
        for (std::size_t i = 0; i < band.size(); ++i)
          sign[i] = phi0[i] / std::sqrt(phi0[i] * phi0[i] + h * h);
        // H = S (|grad phi| - 1) = V . grad phi - S, V = S grad phi /
        // |grad phi|.
        const auto flux = [&](const std::size_t s, const Tensor<1, dim> &g) {
          const double S = simplex_mean(band, sign, s), norm = g.norm();
          return std::make_pair(norm > 0 ? Tensor<1, dim>(S / norm * g) :
                                           Tensor<1, dim>(),
                                S);
        };
        const double       dt         = 0.5 * h;
        const unsigned int iterations = steady_iterations(width, dt, h);
        for (unsigned int k = 0; k < iterations; ++k)
          // (A floor of 1 slows the reinitialisation of a distorted circle
          // past its iteration budget; 0.5 keeps the kinked step stable.)
          step(band, flux, dt, 0.5, fixed, phi);
        return iterations;
      }



      template <int dim>
      unsigned int
      orthogonalise(const SimplexBand<dim>    &band,
                    const std::vector<double> &phi,
                    std::vector<double>       &psi,
                    const double               width)
      {
        if (band.n_simplices() == 0)
          return 0;
        const double h = band.min_height();
        // Each node's velocity V = S(phi) n (n from the node's gradient of
        // phi) and the simplex of its star that holds the backward ray -V:
        // there V . grad lambda_j <= 0 for the other nodes j, and V . grad
        // psi = sum_j (V . grad lambda_j) (psi_j - psi_i) has non-negative
        // weights after the minus of the update (monotone) and is exact
        // for a linear psi. At the body's surface no simplex may hold the
        // ray: the least bad one serves, its downstream nodes left out (as
        // Godunov's rule leaves out a missing neighbour). The weights are
        // fixed: psi is carried along the lines of phi's gradient (a
        // Barth-Sethian distribution of each simplex's residual to its
        // downstream nodes left lst uneven ahead of a kinked front: dips of
        // a cell along the new direction after a few steps).
        std::vector<std::vector<std::pair<unsigned int, double>>> upstream(
          band.size());
        for (std::size_t i = 0; i < band.size(); ++i)
          {
            if (!band.is_active(i))
              continue;
            const Tensor<1, dim> g = gradient(band, phi, i);
            if (g.norm() == 0)
              continue;
            const Tensor<1, dim> V =
              phi[i] / std::sqrt(phi[i] * phi[i] + h * h) / g.norm() * g;
            unsigned int chosen = static_cast<unsigned int>(-1);
            double       best   = std::numeric_limits<double>::max();
            for (const unsigned int s : band.simplices_of(i))
              {
                double worst = -std::numeric_limits<double>::max();
                for (unsigned int j = 0; j <= dim; ++j)
                  if (band.nodes(s)[j] != i)
                    worst = std::max(worst,
                                     V * band.gradients(s)[j] /
                                       band.gradients(s)[j].norm());
                if (worst < best)
                  {
                    best   = worst;
                    chosen = s;
                  }
              }
            if (chosen == static_cast<unsigned int>(-1))
              continue;
            for (unsigned int j = 0; j <= dim; ++j)
              {
                const double k = V * band.gradients(chosen)[j];
                if (band.nodes(chosen)[j] != i && k < 0)
                  upstream[i].emplace_back(band.nodes(chosen)[j], k);
              }
          }
        const double        dt         = 0.5 * h;
        const unsigned int  iterations = steady_iterations(width, dt, h);
        std::vector<double> next(band.size());
        for (unsigned int k = 0; k < iterations; ++k)
          {
            for (std::size_t i = 0; i < band.size(); ++i)
              {
                double rate = 0;
                for (const auto &[j, c] : upstream[i])
                  rate += c * (psi[j] - psi[i]);
                next[i] = psi[i] - dt * rate;
              }
            psi.swap(next);
          }
        return iterations;
      }



#define XCRACK_INSTANTIATE(dim)                                      \
  template void           propagate(const SimplexBand<dim> &,        \
                                    const std::vector<double> &,     \
                                    std::vector<double> &);          \
  template unsigned int   reinitialise(const SimplexBand<dim> &,     \
                                       std::vector<double> &,        \
                                       const double);                \
  template unsigned int   orthogonalise(const SimplexBand<dim> &,    \
                                        const std::vector<double> &, \
                                        std::vector<double> &,       \
                                        const double);               \
  template Tensor<1, dim> gradient(const SimplexBand<dim> &,         \
                                   const std::vector<double> &,      \
                                   const std::size_t);
      XCRACK_INSTANTIATE(2)
      XCRACK_INSTANTIATE(3)
#undef XCRACK_INSTANTIATE
    } // namespace HamiltonJacobi
  }   // namespace LevelSetUpdate
} // namespace xcrack
