#ifndef xcrack_xfem_lip_values_h
#define xcrack_xfem_lip_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Enrichment;

  /**
   * What every term on the crack lips needs at the points of a cell's lip
   * rule (Enrichment::lip_quadrature()): where the points are, the normal
   * times the surface element (n ds, n pointing to the lsn > 0 lip), and the
   * jump [[phi_i]] = phi_i(+) - phi_i(-) of each shape function across the
   * crack (only enriched functions jump), taken from values a hair's
   * breadth off the crack on each side. A lip pressure, contact and, later,
   * cohesion read the same values, as FEValues serves the bulk's terms.
   */
  template <int dim>
  class LipValues
  {
  public:
    explicit LipValues(const Enrichment<dim> &enrichment);

    /// Compute the values on @p cell; returns the number of lip points
    /// (0: the cell has no lips).
    unsigned int
    reinit(const typename DoFHandler<dim>::active_cell_iterator &cell);

    unsigned int
    n_points() const;

    /// The point @p q on the crack (real coordinates).
    const Point<dim> &
    point(const unsigned int q) const;

    /// n ds at point @p q: the unit normal to the lsn > 0 lip times the
    /// point's share of the lips' area (length in 2D).
    const Tensor<1, dim> &
    normal_ds(const unsigned int q) const;

    /**
     * The unit normal of the crack's level set lsn before fit to vertex at
     * point @p q (pointing to the lsn > 0 lip): the direction in which
     * contact measures the gap. Fit to vertex moves the crack through
     * nearby nodes and kinks its lips there by up to `Fit to vertex
     * tolerance` radians; lips that slide along each other would lock at
     * such kinks, which the crack the fields describe does not have.
     * Elsewhere the direction of normal_ds().
     */
    const Tensor<1, dim> &
    crack_normal(const unsigned int q) const;

    /// The jump of the value of shape function @p i (of its one nonzero
    /// component, component(i)) at point @p q.
    double
    jump(const unsigned int i, const unsigned int q) const;

    /// The displacement component shape function @p i belongs to.
    unsigned int
    component(const unsigned int i) const;

    /// The jump [[u]] at point @p q of the field with @p local_values at
    /// the cell's DoFs.
    Tensor<1, dim>
    jump_of(const Vector<double> &local_values, const unsigned int q) const;

  private:
    const Enrichment<dim> &enrichment;

    std::vector<Point<dim>>     points;
    std::vector<Tensor<1, dim>> normals_ds, crack_normals;
    /// jumps[q][i]
    std::vector<std::vector<double>> jumps;
    std::vector<unsigned int>        components;
  };
} // namespace xcrack

#endif
