#ifndef xcrack_level_set_update_simplex_band_h
#define xcrack_level_set_update_simplex_band_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <xcrack/crack/level_set_fields.h>

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * The simplicial split of the mesh's cells near the front, on which the
     * `simplex` update solves the Hamilton-Jacobi equations: each
     * quadrilateral gives 2 triangles and each hexahedron 6 tetrahedra (the
     * Kuhn split along the diagonal from vertex 0 to the opposite one), on
     * the mesh's own vertices. No auxiliary grid and no interpolation: the
     * fields are the mesh's nodal values, and so are the results.
     *
     * Like BandGrid, the band is gathered on every rank (it is small next
     * to the mesh) and the schemes run redundantly, so the result does not
     * depend on the partition: the cells are sorted by their centres before
     * they are numbered. Only the nodes set_active() marks take part, and
     * only the simplices whose nodes all do. At a hanging node the split
     * is not conforming; the scheme does not need it to be (each node
     * gathers what its own simplices send it; the level-set fields keep
     * a value at every node, hanging or not).
     */
    template <int dim>
    class SimplexBand
    {
    public:
      /// The vertices of a cell.
      static constexpr unsigned int n_corners = 1u << dim;

      /// A cell of the mesh as the band needs it: its vertices (in deal.II's
      /// order) and the fields there.
      struct Cell
      {
        std::array<Point<dim>, n_corners> vertices;
        std::array<double, n_corners>     lsn, lst;
      };

      /// The split of @p cells; nodes with the same coordinates are one.
      explicit SimplexBand(std::vector<Cell> cells);

      /**
       * The band of crack @p crack of @p fields: the locally owned cells
       * of every rank that meet @p box, gathered on all ranks. Collective.
       */
      static SimplexBand
      gather(const LevelSetFields<dim> &fields,
             const unsigned int         crack,
             const BoundingBox<dim>    &box,
             const MPI_Comm             communicator);

      /// The number of nodes (active or not).
      std::size_t
      size() const;

      Point<dim>
      point(const std::size_t i) const;

      /// The node at @p x (within a millionth of the shortest edge), or
      /// none.
      std::size_t
      find(const Point<dim> &x) const;

      static constexpr std::size_t none = static_cast<std::size_t>(-1);

      /// The fields at the nodes, as gathered.
      const std::vector<double> &
      lsn() const
      {
        return node_lsn;
      }

      const std::vector<double> &
      lst() const
      {
        return node_lst;
      }

      /// Which nodes take part: the simplices with all nodes active.
      void
      set_active(const std::vector<char> &active);

      bool
      is_active(const std::size_t i) const;

      /// Whether node @p i lost a simplex to an inactive node: the band's
      /// edge, where the schemes lack the information from outside.
      bool
      is_edge(const std::size_t i) const;

      /// The number of simplices that take part.
      std::size_t
      n_simplices() const;

      /// The nodes of simplex @p s.
      const std::array<unsigned int, dim + 1> &
      nodes(const std::size_t s) const
      {
        return simplex_nodes[active_simplices[s]];
      }

      /// The gradients of the barycentric coordinates of simplex @p s.
      const std::array<Tensor<1, dim>, dim + 1> &
      gradients(const std::size_t s) const
      {
        return simplex_gradients[active_simplices[s]];
      }

      double
      volume(const std::size_t s) const
      {
        return simplex_volumes[active_simplices[s]];
      }

      /// The smallest height of the active simplices: the length the
      /// schemes' time steps are measured against.
      double
      min_height() const;

      /// The simplices that take part holding node @p i.
      const std::vector<unsigned int> &
      simplices_of(const std::size_t i) const
      {
        return node_simplices[i];
      }

    private:
      /// The bin of the node index that holds @p x: its coordinates in
      /// units of the tolerance.
      std::array<long long, dim>
      bin(const Point<dim> &x) const;

      std::vector<Point<dim>>                          points;
      std::vector<double>                              node_lsn, node_lst;
      double                                           tolerance = 0;
      std::map<std::array<long long, dim>, unsigned>   index;
      std::vector<std::array<unsigned int, dim + 1>>   simplex_nodes;
      std::vector<std::array<Tensor<1, dim>, dim + 1>> simplex_gradients;
      std::vector<double>                              simplex_volumes;
      std::vector<char>                                active, edge;
      std::vector<unsigned int>                        active_simplices;
      std::vector<std::vector<unsigned int>>           node_simplices;
      double                                           height = 0;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
