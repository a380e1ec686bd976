#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/lapack_templates.h>

#include <xcrack/elastic_cell_matrix.h>

#include <algorithm>
#include <cmath>

namespace xcrack
{
  namespace
  {
    /// Row of the Mandel vector that holds the pair (a, b), a < b.
    template <int dim>
    unsigned int
    shear_row(const unsigned int a, const unsigned int b)
    {
      // 2D: (0,1) -> 2. 3D: (0,1) -> 3, (0,2) -> 4, (1,2) -> 5.
      return dim + a + b - 1;
    }
  } // namespace



  template <int dim>
  void
  ElasticCellMatrix<dim>::compute(const FEValues<dim> &fe_values,
                                  const double         lambda,
                                  const double         mu,
                                  FullMatrix<double>  &cell_matrix)
  {
    const FiniteElement<dim> &fe     = fe_values.get_fe();
    const unsigned int        n_dofs = fe.n_dofs_per_cell();
    const unsigned int        n_q    = fe_values.n_quadrature_points;
    AssertThrow(fe.is_primitive() && fe.n_components() == dim,
                ExcMessage("ElasticCellMatrix needs a primitive element "
                           "with one component per space dimension."));

    component.resize(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      component[i] = fe.system_to_component_index(i).first;

    product.assign(static_cast<std::size_t>(n_dofs) * n_dofs, 0.);
    const double sqrt_half = std::sqrt(0.5);

    for (unsigned int q0 = 0; q0 < n_q; q0 += points_per_block)
      {
        const unsigned int n_block = std::min(points_per_block, n_q - q0);
        const unsigned int rows    = n_block * n_strains;
        strains.assign(static_cast<std::size_t>(rows) * n_dofs, 0.);
        divergences.assign(static_cast<std::size_t>(n_block) * n_dofs, 0.);
        for (unsigned int b = 0; b < n_block; ++b)
          {
            const unsigned int q = q0 + b;
            // The rules are Gauss rules on (sub-)cells: their weights are
            // positive, and the square root splits them between factors.
            Assert(fe_values.JxW(q) >= 0, ExcMessage("Negative weight."));
            const double root_w = std::sqrt(fe_values.JxW(q));
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const unsigned int    c = component[i];
                const Tensor<1, dim> &g = fe_values.shape_grad(i, q);
                double               *column =
                  &strains[static_cast<std::size_t>(i) * rows + b * n_strains];
                // sym(e_c (x) g): g[c] on the diagonal, g[k] / 2 in the
                // pairs (c, k), times sqrt(2) in Mandel notation.
                column[c] = root_w * g[c];
                for (unsigned int k = 0; k < dim; ++k)
                  if (k != c)
                    column[shear_row<dim>(std::min(c, k), std::max(c, k))] =
                      root_w * sqrt_half * g[k];
                divergences[static_cast<std::size_t>(i) * n_block + b] =
                  root_w * g[c];
              }
          }

        // product += 2 mu S^T S + lambda D^T D (lower triangle).
        const types::blas_int n = n_dofs, k_s = rows, k_d = n_block;
        const double          two_mu = 2. * mu, one = 1.;
        syrk("L",
             "T",
             &n,
             &k_s,
             &two_mu,
             strains.data(),
             &k_s,
             &one,
             product.data(),
             &n);
        syrk("L",
             "T",
             &n,
             &k_d,
             &lambda,
             divergences.data(),
             &k_d,
             &one,
             product.data(),
             &n);
      }

    cell_matrix.reinit(n_dofs, n_dofs);
    for (unsigned int j = 0; j < n_dofs; ++j)
      for (unsigned int i = j; i < n_dofs; ++i)
        {
          const double v =
            product[static_cast<std::size_t>(j) * n_dofs + i]; // (i, j)
          cell_matrix(i, j) = v;
          cell_matrix(j, i) = v;
        }
  }



  template class ElasticCellMatrix<2>;
  template class ElasticCellMatrix<3>;
} // namespace xcrack
