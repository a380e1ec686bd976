#ifndef xcrack_crack_mesh_crack_h
#define xcrack_crack_mesh_crack_h

#include <deal.II/grid/tria.h>

#include <xcrack/crack/crack_geometry.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * A crack given by a mesh of its surface: triangles in 3D (quadrilaterals
   * are split), segments in 2D, read from a Gmsh file (MSH 2.2 or 4.1,
   * ASCII) or a legacy ASCII VTK file (POLYDATA or UNSTRUCTURED_GRID). This
   * is how a crack of any shape gets into xcrack, and what a crack grown by
   * an earlier run, or drawn in a CAD tool, looks like.
   *
   * The facets are oriented consistently (from the first one, whose normal
   * by the right-hand rule is the lsn > 0 side); a non-orientable or
   * non-manifold surface is refused. The boundary of the surface (the end
   * points of a 2D polyline) is the front where it lies inside the body,
   * and a mouth where it lies on or outside the body's surface:
   * locate_in() decides once the mesh is known; until then all of it is
   * front.
   *
   * Level sets, by projection on the nearest feature found through
   * boost::geometry R-trees of the facets and of the front edges:
   * - lsn = (p - c) . n, c the point of the surface nearest to p and n the
   *   normal there (the facet's, or the angle-weighted mean over the facets
   *   sharing an edge or vertex, which gives the right side everywhere).
   *   Beyond the front, where c lies on the front, this is the distance to
   *   the surface's tangent extension.
   * - lst = (p - f) . e1, f the point of the front nearest to p and e1 the
   *   outward in-plane normal of the front there: the signed distance to
   *   the front measured in the surface, as Code_Aster builds it from a
   *   crack mesh.
   * With @p band > 0 the projections are made only for points within
   * @p band of the crack's bounding box; farther points get the sign of lsn
   * from the nearest facet's plane and lst = +distance to the box, which is
   * all the enrichment needs of them as long as the band spans a few cells.
   */
  template <int dim>
  class MeshCrack : public CrackGeometry<dim>
  {
  public:
    /**
     * Read @p file_name; @p entry names the prm entry in error messages.
     * Throws InputError for a missing or unreadable file, a file without
     * facets of the right kind, or a surface that is not an orientable
     * manifold.
     */
    MeshCrack(const std::string &file_name,
              const std::string &entry,
              const double       band);
    ~MeshCrack() override;

    /**
     * Make the edges (2D: end points) of the surface's boundary that do not
     * lie strictly inside @p mesh mouths rather than front. Throws
     * InputError if no front is left inside and the crack does not split
     * the body (a crack entirely outside the body).
     */
    void
    locate_in(const Triangulation<dim> &mesh) override;

    double
    lsn(const Point<dim> &p) const override;
    double
    lst(const Point<dim> &p) const override;

    /**
     * The front vertices, ordered along each front (3D: with e3 = e1 x e2
     * pointing along increasing s; several fronts are concatenated, s
     * restarting at 0 on each). @p n_points is ignored: the surface mesh
     * fixes the resolution.
     */
    std::vector<FrontPoint<dim>>
    front(const unsigned int      n_points,
          const BoundingBox<dim> &body) const override;
    BoundingBox<dim>
    bounding_box(const BoundingBox<dim> &body) const override;

    /// Number of facets (triangles in 3D, segments in 2D).
    unsigned int
    n_facets() const;

    /// Number of front edges (3D) or tips (2D).
    unsigned int
    n_front_elements() const;

  private:
    /// A facet: 3 vertex indices (3D) or 2 (2D, last one unused).
    using Facet = std::array<unsigned int, 3>;

    void
    read(const std::string &file_name, const std::string &entry);
    void
    orient_and_connect(const std::string &entry);
    void
    build_front();

    /// Closest point of facet @p f to @p p, and the normal to use there.
    std::pair<Point<dim>, Tensor<1, dim>>
    closest_on_facet(const unsigned int f, const Point<dim> &p) const;

    std::vector<Point<dim>> vertices;
    std::vector<Facet>      facets;
    unsigned int            n_facet_vertices = dim;
    double                  band;

    std::vector<Tensor<1, dim>> facet_normal;
    /// Angle-weighted normals at vertices, mean normals at edges (3D).
    std::vector<Tensor<1, dim>>            vertex_normal;
    std::vector<std::vector<unsigned int>> facets_of_edge_key;
    /// For each facet and local edge (3D) the index of the edge in `edges`.
    std::vector<std::array<unsigned int, 3>> facet_edges;
    std::vector<std::array<unsigned int, 2>> edges;
    std::vector<std::vector<unsigned int>>   edge_facets;
    std::vector<Tensor<1, dim>>              edge_normal;

    /// Boundary edges (3D) or boundary vertices (2D), and which are front.
    std::vector<unsigned int> boundary;
    std::vector<bool>         boundary_is_front;
    /// Outward in-plane normal at each boundary element.
    std::vector<Tensor<1, dim>> boundary_e1;
    /// The front elements (indices into boundary) and their e1 at vertices.
    std::vector<unsigned int>   front_elements;
    std::vector<Tensor<1, dim>> front_vertex_e1;

    BoundingBox<dim> box;

    /// The spatial indices (boost::geometry types stay in the .cc file).
    struct Index;
    std::unique_ptr<Index> index;
  };
} // namespace xcrack

#endif
