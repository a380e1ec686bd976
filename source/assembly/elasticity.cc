#include <xcrack/assembly/elasticity.h>

namespace xcrack
{
  namespace Assembly
  {
    template <int dim>
    Elasticity<dim>::Elasticity(const double lambda, const double mu)
      : lambda(lambda)
      , mu(mu)
    {}



    template <int dim>
    UpdateFlags
    Elasticity<dim>::update_flags() const
    {
      return update_gradients | update_JxW_values;
    }



    template <int dim>
    void
    Elasticity<dim>::assemble(const CellInput<dim> &input,
                              FullMatrix<double>   &matrix,
                              Vector<double> &,
                              std::string &)
    {
      stiffness.compute(*input.fe_values, lambda, mu, cell_matrix);
      matrix.add(1., cell_matrix);
    }



    template class Elasticity<2>;
    template class Elasticity<3>;
  } // namespace Assembly
} // namespace xcrack
