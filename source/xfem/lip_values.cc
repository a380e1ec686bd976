#include <xcrack/xfem/cell_quadrature.h>
#include <xcrack/xfem/enrichment.h>
#include <xcrack/xfem/lip_values.h>

namespace xcrack
{
  template <int dim>
  LipValues<dim>::LipValues(const Enrichment<dim> &enrichment)
    : enrichment(enrichment)
  {}



  template <int dim>
  unsigned int
  LipValues<dim>::reinit(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    points.clear();
    normals_ds.clear();
    crack_normals.clear();
    jumps.clear();
    const auto rule = enrichment.lip_quadrature(cell);
    if (rule.size() == 0)
      return 0;
    const FiniteElement<dim> &fe = cell->get_fe();
    FEValues<dim>             sides(
      fe,
      Quadrature<dim>(CellQuadrature::both_sides(rule.get_points(),
                                                 rule.get_normal_vectors())),
      update_values | update_quadrature_points | update_jacobians);
    sides.reinit(cell);
    components.resize(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      components[i] = fe.system_to_component_index(i).first;
    jumps.resize(rule.size(), std::vector<double>(fe.n_dofs_per_cell()));
    // lsn before fit to vertex: the fitted values plus the shift.
    std::vector<double> lsn    = enrichment.level_set_values(cell).first;
    const auto         &shifts = enrichment.lsn_shift();
    const unsigned int  crack  = enrichment.crack_index(cell);
    if (crack < shifts.size() && !shifts[crack].empty())
      for (const unsigned int v : cell->vertex_indices())
        lsn[v] += shifts[crack][cell->vertex_index(v)];
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        points.push_back(sides.quadrature_point(2 * q));
        normals_ds.push_back(CellQuadrature::mapped_normal<dim>(
          sides.jacobian(2 * q), rule.normal_vector(q), rule.weight(q)));
        Tensor<1, dim> gradient;
        for (unsigned int v = 0; v < lsn.size(); ++v)
          gradient +=
            lsn[v] *
            GeometryInfo<dim>::d_linear_shape_function_gradient(rule.point(q),
                                                                v);
        gradient =
          transpose(invert(Tensor<2, dim>(sides.jacobian(2 * q)))) * gradient;
        crack_normals.push_back(gradient.norm() > 0 ?
                                  gradient / gradient.norm() :
                                  normals_ds.back() / normals_ds.back().norm());
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          jumps[q][i] =
            sides.shape_value(i, 2 * q) - sides.shape_value(i, 2 * q + 1);
      }
    return rule.size();
  }



  template <int dim>
  unsigned int
  LipValues<dim>::n_points() const
  {
    return points.size();
  }



  template <int dim>
  const Point<dim> &
  LipValues<dim>::point(const unsigned int q) const
  {
    return points[q];
  }



  template <int dim>
  const Tensor<1, dim> &
  LipValues<dim>::normal_ds(const unsigned int q) const
  {
    return normals_ds[q];
  }



  template <int dim>
  const Tensor<1, dim> &
  LipValues<dim>::crack_normal(const unsigned int q) const
  {
    return crack_normals[q];
  }



  template <int dim>
  double
  LipValues<dim>::jump(const unsigned int i, const unsigned int q) const
  {
    return jumps[q][i];
  }



  template <int dim>
  unsigned int
  LipValues<dim>::component(const unsigned int i) const
  {
    return components[i];
  }



  template <int dim>
  Tensor<1, dim>
  LipValues<dim>::jump_of(const Vector<double> &local_values,
                          const unsigned int    q) const
  {
    Tensor<1, dim> jump;
    for (unsigned int i = 0; i < local_values.size(); ++i)
      jump[components[i]] += local_values[i] * jumps[q][i];
    return jump;
  }



  template class LipValues<2>;
  template class LipValues<3>;
} // namespace xcrack
