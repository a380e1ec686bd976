#ifndef xcrack_assembly_elasticity_h
#define xcrack_assembly_elasticity_h

#include <xcrack/assembly/interface.h>
#include <xcrack/elastic_cell_matrix.h>

namespace xcrack
{
  namespace Assembly
  {
    /**
     * The bulk's isotropic linear elasticity: the stiffness int sigma(phi_j)
     * : eps(phi_i) over the cell with its X-FEM rule (ElasticCellMatrix).
     * Linear: it adds nothing to b.
     */
    template <int dim>
    class Elasticity : public Contribution<dim>
    {
    public:
      Elasticity(const double lambda, const double mu);

      UpdateFlags
      update_flags() const override;

      void
      assemble(const CellInput<dim> &input,
               FullMatrix<double>   &matrix,
               Vector<double>       &rhs,
               std::string          &culprit) override;

    private:
      const double           lambda, mu;
      ElasticCellMatrix<dim> stiffness;
      FullMatrix<double>     cell_matrix;
    };
  } // namespace Assembly
} // namespace xcrack

#endif
