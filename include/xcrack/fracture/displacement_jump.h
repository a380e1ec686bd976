#ifndef xcrack_fracture_displacement_jump_h
#define xcrack_fracture_displacement_jump_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/material.h>

#include <array>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Enrichment;

  /**
   * K_I, K_II (and K_III in 3D) at a 2D tip or a point of a 3D front from
   * the opening and sliding of the lips behind it, an estimate independent of
   * the interaction integral (and of its crowns): near the tip the Williams
   * field gives
   *
   *   [[u_2]](r) = (kappa + 1) / mu * K_I  * sqrt(r / (2 pi)),
   *   [[u_1]](r) = (kappa + 1) / mu * K_II * sqrt(r / (2 pi)),
   *   [[u_3]](r) = 4 / mu * K_III * sqrt(r / (2 pi)),
   *
   * with [[u]] = u(upper lip, theta = pi) - u(lower lip) in the tip frame.
   * The apparent K(r) of @p n_samples points evenly spread over [@p r_min,
   * @p r_max] behind the tip is fitted by a straight line in r and
   * extrapolated to r = 0, which removes the first correction (the T-stress
   * does not open the lips; the next term of the expansion grows like r).
   * The lips are sampled along -e1 in the plane (e1, e2) of the front
   * point; with @p enrichment each sample is moved onto the discrete lip
   * (the zero of its cell's fitted lsn, along grad lsn) and read in the
   * lip's frame there, so that a crack that kinked or curves behind its tip
   * is followed (without, the straight line misses such lips and the
   * jumps read nothing or the strain of the bulk); samples on lips turned
   * by more than 10 degrees from the tip's plane (beyond a kink, where the
   * field is not the tip's Williams field) are left out. Each sample is read
   * delta = 0.01 @p r_min and 2 delta off the crack on each side:
   * farther than the fit to vertices moves the discrete crack (at 1e-8 r
   * both points of a sample could fall on one side of it where the crack
   * passed near a vertex, and the fit returned K of the wrong sign). The
   * difference across the lip grows linearly with the offset (the strain
   * along e2); 2 d(delta) - d(2 delta) removes that term.
   * Where fewer than half the samples lie on the lips (a crack shorter
   * than the crown, a coarse mesh whose crown leaves the crack) the
   * result is NaN: no estimate. Collective; every rank gets the result. @p
   * cache finds the sampled points' cells: one per mesh, shared by all front
   * points (its vertex to cell map takes longer to build than the samples of
   * one point take).
   */
  template <int dim>
  std::array<double, 3>
  displacement_jump_k(const DoFHandler<dim>               &dof_handler,
                      const GridTools::Cache<dim>         &cache,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const FrontPoint<dim>               &tip,
                      const Material                      &material,
                      const double                         r_min,
                      const double                         r_max,
                      const Enrichment<dim>               *enrichment = nullptr,
                      const unsigned int                   n_samples  = 8);
} // namespace xcrack

#endif
