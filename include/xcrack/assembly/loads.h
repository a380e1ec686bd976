#ifndef xcrack_assembly_loads_h
#define xcrack_assembly_loads_h

#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>

#include <xcrack/assembly/interface.h>
#include <xcrack/xfem/lip_values.h>

namespace xcrack
{
  /**
   * The external loads of a load state, each a linear contribution to b:
   * the tractions on its Neumann boundaries, its body force and the
   * pressure on the lips, all times the state's factor.
   */
  namespace Assembly
  {
    /// int_{Gamma_N} t . phi_i over the cell's faces on a Neumann boundary
    /// of the state's loads.
    template <int dim>
    class BoundaryTractions : public Contribution<dim>
    {
    public:
      BoundaryTractions(const hp::FECollection<dim>    &fe_collection,
                        const hp::QCollection<dim - 1> &face_quadrature);

      void
      assemble(const CellInput<dim> &input,
               FullMatrix<double>   &matrix,
               Vector<double>       &rhs,
               std::string          &culprit) override;

    private:
      hp::FEFaceValues<dim>       face_values;
      std::vector<Vector<double>> load;
    };



    /// int_cell f . phi_i for the state's body force f (none: nothing).
    template <int dim>
    class BodyForce : public Contribution<dim>
    {
    public:
      UpdateFlags
      update_flags() const override;

      void
      assemble(const CellInput<dim> &input,
               FullMatrix<double>   &matrix,
               Vector<double>       &rhs,
               std::string          &culprit) override;

    private:
      std::vector<Vector<double>> load;
    };



    /**
     * The work of a pressure p on the lips in the cell: the integral over
     * the lips of p n . [[phi_i]], where n points to the lsn > 0 lip and
     * [[phi_i]] is the jump of the shape function across the crack
     * (LipValues).
     */
    template <int dim>
    class LipPressure : public Contribution<dim>
    {
    public:
      explicit LipPressure(const Enrichment<dim> &enrichment);

      void
      assemble(const CellInput<dim> &input,
               FullMatrix<double>   &matrix,
               Vector<double>       &rhs,
               std::string          &culprit) override;

    private:
      LipValues<dim> lip_values;
    };
  } // namespace Assembly
} // namespace xcrack

#endif
