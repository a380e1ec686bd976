#ifndef xcrack_level_set_update_simplex_h
#define xcrack_level_set_update_simplex_h

#include <xcrack/level_set_update/interface.h>
#include <xcrack/level_set_update/narrow_band.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * `simplex`: the phases of `upwind` (hamilton_jacobi.h) solved on the
     * mesh itself, split into simplices near the front (SimplexBand), by
     * the simplex scheme of Barth and Sethian (Code_Aster's SIMPLEXE). No
     * auxiliary grid: no interpolation to it and back, no lattice to size,
     * and the band follows the mesh's refinement around the front; in
     * exchange the scheme sees the mesh's cells, so its diffusion is that
     * of the front cells, and a split cell's simplices are flatter than a
     * grid's cells (smaller time steps).
     *
     * Each node of the band takes the advance and kink of its projection
     * on the old front; lsn and lst move, lsn is reinitialised, lst made
     * orthogonal to it and reinitialised, as in `upwind`. Nodes beyond the
     * band keep lsn, and lst keeps its sign. The band is built anew at
     * each step: nothing to checkpoint.
     */
    template <int dim>
    class Simplex : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      check_advance(const double maximum_advance) const override;

      void
      update(const unsigned int                 crack,
             const std::vector<FrontMove<dim>> &moves,
             LevelSetFields<dim>               &fields) override;

    private:
      NarrowBand narrow_band;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
