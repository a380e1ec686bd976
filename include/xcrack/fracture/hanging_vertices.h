#ifndef xcrack_fracture_hanging_vertices_h
#define xcrack_fracture_hanging_vertices_h

#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The hanging vertices of a mesh and the vertices they hang on: the
   * hanging-node constraints of a Q1 field on the triangulation, which also
   * cover vertices hanging on an edge only (3D) and distributed meshes.
   *
   * The interaction integral's linear weight q(r) is interpolated from the
   * cells' vertices. At a vertex that hangs on a coarser neighbour's face
   * its own q(r) differs from the neighbour's interpolation by O(h^2 / (r
   * (r_sup - r_inf))), so q would jump across that face and the domain form
   * (q in H^1) lose a face term: K then moved with every refinement that
   * left hanging faces inside the crown. There q takes its masters'
   * interpolation instead (doc/verification.md, "q across hanging faces").
   */
  template <int dim>
  class HangingVertices
  {
  public:
    explicit HangingVertices(const Triangulation<dim> &triangulation);

    /**
     * The vertices vertex @p v of @p cell (owned or ghost) hangs on, with
     * their weights; empty where it does not hang.
     */
    std::vector<std::pair<Point<dim>, double>>
    masters(const typename Triangulation<dim>::active_cell_iterator &cell,
            const unsigned int                                       v) const;

  private:
    const FE_Q<dim>                               fe;
    DoFHandler<dim>                               dof_handler;
    AffineConstraints<double>                     constraints;
    std::map<types::global_dof_index, Point<dim>> support_points;
  };
} // namespace xcrack

#endif
