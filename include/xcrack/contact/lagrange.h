#ifndef xcrack_contact_lagrange_h
#define xcrack_contact_lagrange_h

#include <deal.II/lac/full_matrix.h>

#include <xcrack/contact/interface.h>
#include <xcrack/contact/multiplier_space.h>
#include <xcrack/simulator_access.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace xcrack
{
  namespace Contact
  {
    /**
     * `lagrange`: the contact tractions as unknowns of their own, Lagrange
     * multipliers on a space of the lips (MultiplierSpace, `Multiplier
     * space`), and the lips held exactly. Each multiplier k of the space
     * carries a pressure lambda_k and, with friction, a tangential traction
     * lambda_T,k (dim - 1 components in a frame of its own, t_1 .. t_{d-1}
     * orthogonal to the mean normal of its lips); on the lips p = sum_k
     * lambda_k psi_k pushes them apart and t = P_T sum_k lambda_T,k psi_k
     * acts on the lsn > 0 lip: -int (p n + t) . [[v]] ds in the equilibrium.
     * The weighted gap and slips of a multiplier are
     *
     *     g_k(u) = int psi_k n . [[u]] ds,   s_k(u) = int psi_k t_k . P_T [[u]]
     * ds.
     *
     * Its status follows from the iterate by Alart and Curnier's
     * complementarity functions (the semi-smooth Newton method of Hueber,
     * Stadler and Wohlmuth, SIAM J. Sci. Comput. 30 (2008) 572; deal.II's
     * step-41 for an obstacle), with m_k = int psi_k ds and c =
     * `Complementarity coefficient` E / h:
     * - open where lambda_k - c g_k / m_k <= 0: lambda_k = 0, lambda_T,k = 0;
     * - else closed, g_k = 0, and with friction, tau = lambda_T,k - c s_k /
     *   m_k against Coulomb's bound mu (lambda_k - c g_k / m_k):
     *   sticking within it (s_k = 0), slipping beyond it (lambda_T,k = mu
     *   lambda_k d, d = tau / |tau| of the iterate).
     *
     * The conditions are linear once the statuses (and slip directions) are
     * known, so a solve is exact when they settle; c only weighs a gap
     * against a pressure when they are updated. A solve starts closed and
     * sticking everywhere (as the penalty does), so that a piece the crack
     * cuts off rests on the lips from the first step. An open multiplier
     * keeps the row -(m_k h / E) lambda_k = 0. The system is a saddle point
     * [A, -B^T; -B, 0]: symmetric and indefinite without friction (MUMPS
     * LDL^T), unsymmetric where lips slip (LU).
     *
     * A multiplier whose lips carry no jump (cells the front touches
     * without tip enrichment) stays open. Refused: DOF gathering, whose few
     * branch unknowns carry the jump of the whole tip zone and cannot meet a
     * multiplier per vertex there.
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

      /// Per multiplier of the space: its pressure, and with friction its
      /// tangential tractions after it.
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
      /// A multiplier's status.
      enum Status : char
      {
        opened,
        sticking,
        slipping
      };

      /// Unknowns per multiplier of the space (1, or dim with friction).
      unsigned int
      n_components() const;

      /// What a locally owned cell with lips contributes, computed once per
      /// space.
      struct CellData
      {
        typename DoFHandler<dim>::active_cell_iterator cell;
        /// The cell's multipliers (MultiplierSpace::CellBasis).
        std::vector<unsigned int> multipliers;
        /// coupling(j, i) = int psi_j n . [[phi_i]] ds over the cell's lips;
        /// with friction tangential(j (dim - 1) + k, i) = int psi_j t_k .
        /// P_T [[phi_i]] ds, t_k of multiplier j's frame.
        FullMatrix<double> coupling, tangential;
        /// gap_rows(q, i) = n . [[phi_i]] at lip point q; jumps(q, i) the
        /// jump of phi_i (of its component components[i]).
        FullMatrix<double>        gap_rows, jumps;
        std::vector<unsigned int> components;
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

      /// The tangential traction at lip point @p q of @p data (on the
      /// lsn > 0 lip).
      Tensor<1, dim>
      friction_traction(const CellData &data, const unsigned int q) const;

      /// The frames of the multipliers: their lips' mean normal and the
      /// tangents orthogonal to it (collective).
      void
      make_frames();

      /// The statuses of the current iterate from its gaps and slips.
      void
      update_statuses();

      MultiplierSpace<dim> space;
      double               complementarity = 1;

      std::map<CellId, CellData> cells;
      /// Per multiplier of the space, on every rank: its pressure and
      /// tangential tractions, its weighted gap and slips at the last
      /// iterate, int psi ds, the mean E / h of its cells, whether its lips
      /// carry a jump at all, its frame, its status in the system last
      /// assembled and, slipping, the direction of its friction traction.
      std::vector<double>                      lambda, gap, mass, stiffness;
      std::vector<std::array<double, dim - 1>> lambda_t, slip, direction;
      std::vector<Tensor<1, dim>>              normal;
      std::vector<std::array<Tensor<1, dim>, dim - 1>> tangents;
      std::vector<char>                                coupled, status;
      /// Multipliers of this rank's range whose status the last assembly
      /// changed, and where the first of them is.
      unsigned int n_changed = 0;
      Point<dim>   first_changed;
    };
  } // namespace Contact
} // namespace xcrack

#endif
