#ifndef xcrack_contact_lagrange_h
#define xcrack_contact_lagrange_h

#include <deal.II/lac/full_matrix.h>

#include <xcrack/contact/interface.h>
#include <xcrack/contact/multiplier_space.h>
#include <xcrack/simulator_access.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace xcrack
{
  namespace Contact
  {
    /**
     * `lagrange`: the contact pressure as unknowns of its own, Lagrange
     * multipliers lambda_k on a space of the lips (MultiplierSpace,
     * `Multiplier space`), and the lips held exactly: where a multiplier is
     * active, the weighted gap
     *
     *     g_k(u) = int_lips psi_k n . [[u]] ds = 0,
     *
     * elsewhere lambda_k = 0; the pressure p = sum_k lambda_k psi_k pushes
     * the lips apart (-int p n . [[v]] ds in the equilibrium). The system is
     * a saddle point [A, -B^T; -B, 0], symmetric and indefinite, which the
     * direct solver factors as such (LDL^T).
     *
     * Which multipliers are active follows from the iterate by the
     * complementarity function of the primal-dual active set method
     * (Hintermueller, Ito and Kunisch, SIAM J. Optim. 13 (2003) 865; the
     * semi-smooth Newton method deal.II's step-41 applies to an obstacle):
     * active where lambda_k - c g_k / m_k > 0, m_k = int psi_k ds and c =
     * `Complementarity coefficient` E / h. The constraint is linear once the
     * active set is known, so a solve is exact when the set settles; c only
     * weighs a gap against a pressure when the set is updated (it does not
     * change the solution). A solve starts with every multiplier active
     * (closed lips), so that a piece the crack cuts off rests on them from
     * the first step, as with the penalty. An inactive multiplier keeps the
     * row -(m_k h / E) lambda_k = 0, so that the matrix stays symmetric.
     *
     * A multiplier whose lips carry no jump (cells the front touches
     * without tip enrichment) stays inactive. Refused: DOF gathering, whose
     * few branch unknowns carry the jump of the whole tip zone and cannot
     * satisfy a multiplier per vertex there. Friction is not available with
     * this formulation yet (penalty or augmented lagrangian).
     */
    template <int dim>
    class Lagrange : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      /// Refuses a space the multipliers would not be stable on.
      void
      initialize() override;

      bool
      allows_friction() const override
      {
        return false;
      }

      /// @name Assembly::Contribution
      /// @{
      void
      start_assembly(const bool first) override;

      /// Nothing in the displacement block: the lips act through the
      /// multipliers.
      void
      assemble(const Assembly::CellInput<dim> &input,
               FullMatrix<double>             &matrix,
               Vector<double>                 &rhs,
               std::string                    &culprit) override;

      std::pair<unsigned int, std::string>
      changed_statuses() const override;

      bool
      has_own_unknowns() const override
      {
        return true;
      }

      void
      setup_own_unknowns() override;

      unsigned int
      n_own_unknowns() const override;

      std::pair<unsigned int, unsigned int>
      owned_own_unknowns() const override;

      std::vector<unsigned int>
      own_unknowns_of(const typename DoFHandler<dim>::active_cell_iterator
                        &cell) const override;

      void
      assemble_own(const Assembly::CellInput<dim> &input,
                   const unsigned int              n_dofs,
                   FullMatrix<double>             &matrix,
                   Vector<double>                 &rhs) override;

      void
      set_own_values(const std::vector<double> &values) override;
      /// @}

      Tensor<1, dim>
      lip_traction(const CellId &cell, const unsigned int q) const override;

      typename Interface<dim>::LipState
      lip_state(const CellId &cell) const override;

      double
      closed_fraction(const Point<dim> &x, const double radius) const override;

      std::map<std::string, double>
      statistics() const override;

    private:
      /// What a locally owned cell with lips contributes, computed once per
      /// space.
      struct CellData
      {
        typename DoFHandler<dim>::active_cell_iterator cell;
        /// The cell's multipliers (MultiplierSpace::CellBasis).
        std::vector<unsigned int> multipliers;
        /// coupling(j, i) = int psi_j n . [[phi_i]] ds over the cell's lips.
        FullMatrix<double> coupling;
        /// gap_rows(q, i) = n . [[phi_i]] at lip point q.
        FullMatrix<double> gap_rows;
        /// int psi_j ds over the cell's lips.
        std::vector<double> mass;
        /// At each lip point: psi_j, the unit normal, ds, where it is, and
        /// the gap n . [[u]] of the last iterate.
        std::vector<std::vector<double>> psi;
        std::vector<Tensor<1, dim>>      normals;
        std::vector<double>              ds;
        std::vector<Point<dim>>          points;
        std::vector<double>              gaps;
        /// E / h of the cell.
        double stiffness = 0;
      };

      /// The pressure at lip point @p q of @p data.
      double
      pressure(const CellData &data, const unsigned int q) const;

      MultiplierSpace<dim> space;
      double               complementarity = 1;

      std::map<CellId, CellData> cells;
      /// Per multiplier, on every rank: its value, its weighted gap at the
      /// last iterate, int psi ds, the mean E / h of its cells, whether its
      /// lips carry a jump at all, and whether it is active in the system
      /// last assembled.
      std::vector<double> lambda, gap, mass, stiffness;
      std::vector<char>   coupled, active;
      /// Multipliers of this rank's range whose status the last assembly
      /// changed, and where the first of them is.
      unsigned int n_changed = 0;
      Point<dim>   first_changed;
    };
  } // namespace Contact
} // namespace xcrack

#endif
