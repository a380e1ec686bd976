#ifndef xcrack_contact_multiplier_space_h
#define xcrack_contact_multiplier_space_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/cell_id.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Enrichment;

  namespace Contact
  {
    /**
     * The space of the contact pressure of the Lagrange formulation on the
     * crack lips (`Lagrange/Multiplier space`), built from where the lips
     * cross the edges of the cells. A crossing of edge (a, b) has the
     * function w = N_a + N_b on the cell (N the Q1 shape functions: one on
     * the edge, zero on the faces without a or b; a vertex on the lips, N_a).
     * On the lips of a cell K with crossings C_K, multiplier k has
     *
     *     psi_k = sum of w over k's crossings in K / sum of w over C_K:
     *
     * the functions of a cell sum to one (the space holds the constant
     * pressure of the patch test), and along a 2D lip that crosses two
     * opposite edges they are P1 between the crossings.
     *
     * Which crossings share a multiplier decides whether the pressure is
     * stable (the inf-sup condition between the multipliers and the jumps
     * of the enriched displacement):
     * - `edges`: one multiplier per crossing, the naive space (Ji and
     *   Dolbow, IJNME 61 (2004) 2508). Where the crack passes near a
     *   vertex, the enriched DoF of that vertex alone controls the jump at
     *   several crossings around it, each with a multiplier of its own:
     *   the pressures oscillate.
     * - `vital nodes`: a crossing belongs to the nearer vertex of its edge,
     *   and the crossings of one vertex share one multiplier, so that each
     *   multiplier pairs with the enriched DoF of its vertex and a piece of
     *   lip cut off near a corner gets that corner's multiplier. It is a
     *   subspace of `edges` (the crossings tied together, as Code_Aster's
     *   X-FEM contact ties the multipliers of its vital edges; Bechet, Moes
     *   and Wohlmuth, IJNME 78 (2009) 931, vital vertices), with the
     *   simplest rule that picks the vertices: the nearer one.
     * - `cells`: one constant pressure per cell with lips (the penalty's
     *   `cells`), stable except where a cell holds a sliver of lip whose
     *   jump a neighbour's vertex controls.
     *
     * A cell whose lips cross no edge (a piece ending inside it) takes a
     * multiplier at its vertex nearest to them. Multipliers are keyed by
     * where they sit (a vertex, an edge's middle, a cell's centre), so that
     * every rank that sees one numbers it alike; a multiplier is owned by
     * the lowest rank with a cell that uses it, and each rank's owned
     * multipliers are numbered contiguously.
     */
    template <int dim>
    class MultiplierSpace
    {
    public:
      enum class Type
      {
        vital_nodes,
        edges,
        cells
      };

      /// "vital nodes|edges|cells", for a Patterns::Selection.
      static std::string
      names();

      /// The type called @p name (one of names()).
      static Type
      parse(const std::string &name);

      explicit MultiplierSpace(const Type type = Type::vital_nodes);

      Type
      type() const;

      /**
       * Build the space on the lips of the locally owned cells of
       * @p dof_handler, whose cracks @p enrichment describes (collective).
       */
      void
      reinit(const DoFHandler<dim> &dof_handler,
             const Enrichment<dim> &enrichment,
             const MPI_Comm         comm);

      /// The multipliers over all ranks.
      unsigned int
      size() const;

      /// [begin, end) of those this rank owns.
      std::pair<unsigned int, unsigned int>
      owned_range() const;

      /// Where multiplier @p k sits (its vertex, its edge's middle or its
      /// cell's centre).
      const Point<dim> &
      location(const unsigned int k) const;

      /// A cell's multipliers and their basis functions at its lip points.
      struct CellBasis
      {
        std::vector<unsigned int> multipliers;
        /// values[q][j]: psi of multipliers[j] at lip point q (the points
        /// of Enrichment::lip_quadrature()).
        std::vector<std::vector<double>> values;
      };

      /// The basis on the locally owned @p cell; null if it has no lips.
      const CellBasis *
      basis(const CellId &cell) const;

    private:
      Type                          type_;
      std::vector<Point<dim>>       locations;
      std::pair<unsigned, unsigned> owned = {0, 0};
      std::map<CellId, CellBasis>   bases;
    };
  } // namespace Contact
} // namespace xcrack

#endif
