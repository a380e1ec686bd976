#ifndef xcrack_crack_crack_set_h
#define xcrack_crack_crack_set_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>

#include <xcrack/crack/crack_geometry.h>

#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The cracks of a scene (`subsection Cracks`): `Number of cracks`
   * independent cracks, each described in `subsection Crack <i>` by a shape
   * and its placement:
   *
   * - 2D `segment`: `Start point`, `End point`, and `Tips` (both ends, or
   *   only the end or the start when the other end is a mouth on the
   *   boundary, as for an edge crack);
   * - 3D `half plane` (a point of the straight front, the normal, and the
   *   `In-plane direction` e1 in which the front would advance), `penny`
   *   (`Radius`), `ellipse` (`Semi-axes` a along the in-plane direction and
   *   b across it; centre it on a face for a semi-elliptical surface crack),
   *   `rectangle` (`Size`: width along the in-plane direction, height
   *   across), each with `Center` and `Normal`;
   * - 2D or 3D `mesh`: a crack surface mesh (`File name`, see MeshCrack).
   *
   * check_against() rejects a crack that does not cut the mesh and a tip
   * outside the body, naming the crack.
   */
  template <int dim>
  class CrackSet
  {
  public:
    static constexpr unsigned int max_cracks = 8;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Parse every crack; throws InputError naming the crack and entry.
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Place each crack in the mesh (CrackGeometry::locate_in: a crack
     * surface mesh finds its front there) and check it: its surface must
     * cut at least one cell, and every 2D tip must lie inside the body.
     */
    void
    check_against(const parallel::distributed::Triangulation<dim> &mesh);

    unsigned int
    size() const;

    const CrackGeometry<dim> &
    operator[](const unsigned int i) const;

    /// The shapes of all cracks, in order (for LevelSetFields::initialize).
    std::vector<const CrackGeometry<dim> *>
    shapes() const;

  private:
    std::vector<std::unique_ptr<CrackGeometry<dim>>> cracks;
  };
} // namespace xcrack

#endif
