#ifndef xcrack_crack_facet_crack_h
#define xcrack_crack_facet_crack_h

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/crack/facet_surface.h>

#include <string>
#include <vector>

namespace xcrack
{
  /**
   * A crack started from the surface an earlier run's `crack mesh`
   * level-set update wrote (`Shape = mesh`, `File name =
   * crack_mesh-<step>.vtu`): its facets and fronts, with the direction of
   * growth at each front node. The level sets are those the update gave at
   * that step (FacetSurface); the `crack mesh` update of the new run goes on
   * growing this surface rather than one drawn from the fields, so that it
   * takes the step the earlier run took next (on the mesh the new run
   * refines).
   */
  template <int dim>
  class FacetCrack : public CrackGeometry<dim>
  {
  public:
    /// Read @p file_name; @p entry names the prm entry in error messages.
    FacetCrack(const std::string &file_name, const std::string &entry);

    double
    lsn(const Point<dim> &p) const override;
    double
    lst(const Point<dim> &p) const override;

    /**
     * The front nodes with their frames (e1 as written; e2 the normal of
     * the nearest facet made normal to e1, in 2D e1 turned by +90
     * degrees), ordered along each front; several fronts are concatenated,
     * s restarting at 0 on each. @p n_points is ignored.
     */
    std::vector<FrontPoint<dim>>
    front(const unsigned int      n_points,
          const BoundingBox<dim> &body) const override;

    BoundingBox<dim>
    bounding_box(const BoundingBox<dim> &body) const override;

    /// The surface as read.
    const FacetSurface<dim> &
    surface() const;

  private:
    FacetSurface<dim> facets;
  };
} // namespace xcrack

#endif
