#ifndef xcrack_crack_facet_surface_h
#define xcrack_crack_facet_surface_h

#include <deal.II/base/point.h>

#include <array>
#include <boost/serialization/array.hpp>
#include <boost/serialization/vector.hpp>
#include <memory>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * A crack surface as a set of oriented facets (segments in 2D, triangles
   * in 3D) and its fronts (points in 2D, polylines in 3D, each point with
   * the direction e1 the crack grows in), and the level sets they give by
   * projection: what the `crack mesh` level-set update keeps from step to
   * step and extends by the strip each advance sweeps.
   *
   * Unlike MeshCrack (a crack surface file), the facets need not share
   * vertices: the lips extracted from the fields are a polygon per cell
   * (with T-junctions at hanging nodes), and the strips meet them along
   * the old front only up to rounding. So no connectivity is built:
   * - lsn(p) = (p - c) . n, c the point of the facets nearest to p and n
   *   the normal of its facet (to the lsn > 0 side); where several facets
   *   share c (an edge or corner, up to rounding), the value of largest
   *   magnitude, i.e. the facet whose normal p - c follows best, which
   *   gives the side of a kinked surface right on its convex side. Beyond
   *   the surface's boundary this is the distance to its tangent
   *   extension, as MeshCrack and Code_Aster define it.
   * - lst(p): with f the point of the fronts nearest to c and e1 the
   *   direction of growth there (interpolated along a polyline), (p - f) .
   *   e1 where c lies on a front, -|c - f| where it lies inside the
   *   surface: the signed distance to the front measured in the surface.
   *
   * Every rank holds the whole surface. Nearest points are found through
   * boost::geometry R-trees of the facets' and front segments' boxes.
   */
  template <int dim>
  class FacetSurface
  {
  public:
    /// A segment (2D) or triangle (3D) with its unit normal.
    struct Facet
    {
      std::array<Point<dim>, dim> corners;
      Tensor<1, dim>              normal;
      /// The step that added it (0: the crack as the fields first drew it).
      unsigned int step = 0;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &corners &normal &step;
      }
    };

    /// A point of a front with the unit direction of growth there.
    struct FrontNode
    {
      Point<dim>     position;
      Tensor<1, dim> e1;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &position &e1;
      }
    };

    FacetSurface();
    FacetSurface(const FacetSurface &other);
    FacetSurface &
    operator=(const FacetSurface &other);
    ~FacetSurface();

    /// Add @p new_facets (facets of no extent are dropped).
    void
    add(const std::vector<Facet> &new_facets);

    /// Replace the fronts (each a chain of nodes; in 2D one node each).
    void
    set_fronts(const std::vector<std::vector<FrontNode>> &new_fronts);

    const std::vector<Facet> &
    facets() const;

    const std::vector<std::vector<FrontNode>> &
    fronts() const;

    bool
    empty() const;

    /**
     * The point of the facets nearest to @p p and the normal there (see
     * the class documentation for shared edges and corners). The surface
     * must not be empty.
     */
    std::pair<Point<dim>, Tensor<1, dim>>
    nearest(const Point<dim> &p) const;

    /// The normal level set at @p p.
    double
    lsn(const Point<dim> &p) const;

    /// The point of the fronts nearest to @p p and the direction e1 there.
    std::pair<Point<dim>, Tensor<1, dim>>
    nearest_on_front(const Point<dim> &p) const;

    /// The tangent level set at @p p (the fronts must not be empty).
    double
    lst(const Point<dim> &p) const;

    /**
     * Write the facets (with their normal and the step that added them as
     * cell data) and the fronts to @p out as an XML VTU file ParaView
     * reads.
     */
    void
    write_vtu(std::ostream &out) const;

    /**
     * The surface that write_vtu() wrote to @p in; @p what names the file
     * (and the entry) in error messages. Throws InputError for a file that
     * is not such a surface or whose facets do not fit the dimension
     * (triangles in 2D, segments in 3D, z != 0 in 2D).
     */
    static FacetSurface
    read_vtu(std::istream &in, const std::string &what);

    template <class Archive>
    void
    save(Archive &archive, const unsigned int) const
    {
      archive &facet_list &front_list;
    }

    template <class Archive>
    void
    load(Archive &archive, const unsigned int)
    {
      archive &facet_list &front_list;
      drop_index();
    }

    BOOST_SERIALIZATION_SPLIT_MEMBER()

  private:
    /// Build the R-trees if a change made them stale.
    void
    build_index() const;

    /// Make the R-trees stale.
    void
    drop_index();

    std::vector<Facet>                  facet_list;
    std::vector<std::vector<FrontNode>> front_list;

    /// The spatial indices (boost::geometry types stay in the .cc file).
    struct Index;
    mutable std::unique_ptr<Index> index;
  };
} // namespace xcrack

#endif
