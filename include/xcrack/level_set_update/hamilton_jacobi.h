#ifndef xcrack_level_set_update_hamilton_jacobi_h
#define xcrack_level_set_update_hamilton_jacobi_h

#include <deal.II/base/tensor.h>

#include <xcrack/level_set_update/band_grid.h>
#include <xcrack/level_set_update/simplex_band.h>

#include <vector>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * The phases of a Hamilton-Jacobi level-set update on a BandGrid
     * (Gravouil, Moes and Belytschko 2002; the seed's `upwind` method),
     * first order in space with upwind (Godunov) differences, explicit in
     * pseudo-time. Every function works on the active points only; a
     * missing neighbour (the band's edge, the body's surface) brings no
     * information: no ghost point, nothing extrapolated beyond the band.
     */
    namespace HamiltonJacobi
    {
      /**
       * Integrate phi_t + V |grad phi| = 0 over a unit of pseudo-time, V =
       * @p speed per point (CFL 1/2).
       */
      template <int dim>
      void
      propagate(const BandGrid<dim>       &grid,
                const std::vector<double> &speed,
                std::vector<double>       &phi);

      /**
       * Make @p phi a signed distance to its zero set in the band: phi_t +
       * S(phi_0) (|grad phi| - 1) = 0 to a steady state. The points next to
       * the zero set (a neighbour of the other sign) are not evolved: they
       * are set once to phi_0 / |grad phi_0|, their distance to the
       * linearised zero set (Russo and Smereka's fix), so that the zero set
       * does not move with the iterations. Returns the iterations taken;
       * stops when no value changes by more than @p tolerance grid
       * spacings, or after the pseudo-time that crosses @p width.
       */
      template <int dim>
      unsigned int
      reinitialise(const BandGrid<dim> &grid,
                   std::vector<double> &phi,
                   const double         width,
                   const double         tolerance = 1e-4);

      /**
       * Make grad @p psi orthogonal to grad @p phi: psi_t + S(phi) n . grad
       * psi = 0, n = grad phi / |grad phi|, to a steady state (upwind along
       * n): psi is carried away from the zero set of phi along its normals,
       * so the zero set of psi on that of phi (the front) stays. Returns the
       * iterations taken; the same stopping rule as reinitialise().
       */
      template <int dim>
      unsigned int
      orthogonalise(const BandGrid<dim>       &grid,
                    const std::vector<double> &phi,
                    std::vector<double>       &psi,
                    const double               width,
                    const double               tolerance = 1e-4);

      /// The largest number of iterations of a steady-state phase: the
      /// pseudo-time that crosses @p width in steps of @p dt, with a margin
      /// of two cells of size @p h.
      unsigned int
      steady_iterations(const double width, const double dt, const double h);

      /// The iterations the steady-state phases of move_front() took.
      struct Iterations
      {
        unsigned int reinitialise_phi = 0, orthogonalise = 0,
                     reinitialise_psi = 0;
      };

      /**
       * The five phases of a step of a front: lsn @p phi and lst @p psi
       * (signed distances) move so that the front, where both are zero,
       * advances by @p advance per point along its direction turned by
       * @p kink (radians, positive towards phi > 0), the crack behind it
       * (phi = 0, psi < 0) staying where it is:
       *
       * 1. phi_t + V |grad phi| = 0, V = max(psi, 0) asinh(tan(kink)):
       *    ahead of the front the zero set turns about it by the kink;
       * 2. psi_t + advance cos(kink) |grad psi| = 0;
       * 3. phi reinitialised; 4. psi made orthogonal to phi; 5. psi
       *    reinitialised;
       *
       * each steady-state phase over the pseudo-time that crosses
       * @p width. @p Band is a BandGrid (finite differences) or a
       * SimplexBand (the simplex scheme): the phases are the same.
       */
      template <class Band>
      Iterations
      move_front(const Band                &grid,
                 const std::vector<double> &kink,
                 const std::vector<double> &advance,
                 const double               width,
                 std::vector<double>       &phi,
                 std::vector<double>       &psi);

      /// The gradient of @p phi at active point @p i: central differences,
      /// one-sided where a neighbour is missing, 0 where both are.
      template <int dim>
      Tensor<1, dim>
      gradient(const BandGrid<dim>       &grid,
               const std::vector<double> &phi,
               const std::size_t          i);



      /**
       * The same phases on a SimplexBand, by the simplex scheme (Barth and
       * Sethian 1998; Code_Aster's SIMPLEXE): phi is P1 on each simplex, so
       * its gradient is constant there, and H is linearised about it (V =
       * dH/d(grad phi)). propagate() and reinitialise() send each
       * simplex's residual to its downstream nodes (those V points to);
       * a node takes it from the simplices of which it is the only
       * downstream node where it has any (monotone), else the weighted mean
       * over the others. orthogonalise(), whose V is known beforehand,
       * updates each node from the simplex of its star that holds its
       * backward characteristic (monotone and exact for a linear psi). A
       * node that receives nothing (upstream of all its simplices, or at
       * the band's edge) keeps its value: first-order upwinding without a
       * lattice. Same
       * arguments and results as the BandGrid versions, except that the
       * steady-state phases run a fixed number of iterations (the
       * pseudo-time that crosses @p width): they seldom meet a tolerance
       * (a node where characteristics meet, as at a kink, keeps moving by
       * a little), and a stopping test would make the result jump with
       * the round-off of its input (one iteration more on one rank than
       * on two).
       */
      template <int dim>
      void
      propagate(const SimplexBand<dim>    &band,
                const std::vector<double> &speed,
                std::vector<double>       &phi);

      template <int dim>
      unsigned int
      reinitialise(const SimplexBand<dim> &band,
                   std::vector<double>    &phi,
                   const double            width);

      template <int dim>
      unsigned int
      orthogonalise(const SimplexBand<dim>    &band,
                    const std::vector<double> &phi,
                    std::vector<double>       &psi,
                    const double               width);

      /// The gradient of @p phi at node @p i: the mean of its simplices'
      /// (constant) gradients, weighted by their volumes.
      template <int dim>
      Tensor<1, dim>
      gradient(const SimplexBand<dim>    &band,
               const std::vector<double> &phi,
               const std::size_t          i);
    } // namespace HamiltonJacobi
  }   // namespace LevelSetUpdate
} // namespace xcrack

#endif
