#ifndef xcrack_contact_penalty_h
#define xcrack_contact_penalty_h

#include <xcrack/contact/interface.h>
#include <xcrack/simulator_access.h>
#include <xcrack/xfem/lip_values.h>

#include <map>
#include <memory>
#include <vector>

namespace xcrack
{
  namespace Contact
  {
    /**
     * `penalty`: where the lips interpenetrate (g <= 0) they press on each
     * other with p = kappa (-g), as if joined by stiff springs; where they
     * open, nothing. The energy kappa/2 int <-g>_+^2 adds, at a closed
     * point, kappa (n . [[phi_i]]) (n . [[phi_j]]) ds to the tangent and
     * nothing to the right-hand side (the lips coincide before the load):
     * a system as symmetric and definite as elasticity's, solved exactly
     * once the Newton loop has found the closed points. A solve starts
     * with every point closed (its first iterate is zero), so that a piece
     * the crack cuts off rests on the lips from the first step: lips that
     * open take one or two more steps.
     *
     * kappa = `Penalty coefficient` E / h, h the size of the cell (the
     * stiffness of a cell's worth of material), so that the coefficient
     * says how much stiffer than the material the springs are: the lips
     * interpenetrate by about p h / (coefficient E), and K_I of a closed
     * crack is about that fraction of the load's K (doc/verification.md,
     * "Crack lips that touch"). Large coefficients approach exact contact
     * and condition the system worse (the Newton loop also needs more
     * steps when many points change status at once).
     *
     * With friction, closed lips are held in their tangent plane by springs
     * of stiffness kappa_T = `Tangential penalty coefficient` E / h: the
     * trial traction t = -kappa_T s. Where |t| <= mu p they stick (the
     * springs hold them: a slip of order mu p h / (coefficient E) remains);
     * elsewhere they slip, t = -mu p s / |s|, whose tangent couples the
     * tangential force to the gap and is not symmetric. Both forces are
     * homogeneous of degree one in u, so the Newton step's right-hand side
     * stays zero; in 2D the slipping force is linear once its direction is
     * known, and the solve is exact once the statuses settle.
     *
     * The same springs serve the augmented Lagrangian formulation
     * (AugmentedLagrangian, below), which adds multipliers to them.
     */
    template <int dim>
    class Penalty : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      start_assembly(const bool first) override;

      void
      assemble(const Assembly::CellInput<dim> &input,
               FullMatrix<double>             &matrix,
               Vector<double>                 &rhs,
               std::string                    &culprit) override;

      std::pair<unsigned int, std::string>
      changed_statuses() const override;

      Tensor<1, dim>
      lip_traction(const CellId &cell, const unsigned int q) const override;

      std::map<std::string, double>
      statistics() const override;

      typename Interface<dim>::LipState
      lip_state(const CellId &cell) const override;

      double
      closed_fraction(const Point<dim> &x, const double radius) const override;

    protected:
      /**
       * Declare, in subsection @p section, `Pressure space` and the
       * springs' coefficients `<name> coefficient` and `Tangential <name>
       * coefficient` (@p name in lower case in the latter), defaulting to
       * @p default_value; parse them back with parse_springs().
       */
      static void
      declare_springs(ParameterHandler  &prm,
                      const std::string &section,
                      const std::string &name,
                      const std::string &default_value);

      void
      parse_springs(ParameterHandler  &prm,
                    const std::string &section,
                    const std::string &name);

      /// Whether the springs carry multipliers (AugmentedLagrangian).
      bool augmented = false;

    private:
      /// A group's multipliers: the pressure and the tangential traction
      /// that the springs' forces are added to (zero for the penalty).
      struct Multipliers
      {
        double         normal = 0;
        Tensor<1, dim> tangential;
      };

      /**
       * Add the tangent of friction at one closed group to @p matrix and
       * the Newton step's share A u_k - F(u_k) to @p rhs, and return the
       * tangential traction on the lsn > 0 lip: @p slip the group's mean
       * slip, @p multiplier its tangential multiplier, @p mean_slip[i] the
       * mean of P_T [[phi_i]], @p mean_gap[i] that of n . [[phi_i]],
       * @p pressure the group's contact pressure, @p kappa and @p kappa_t
       * the springs' stiffnesses, @p length the group's length (area),
       * @p iterate the cell's values of u_k (null at a solve's first step).
       * @p sliding says whether the group slips.
       */
      Tensor<1, dim>
      add_friction(const Tensor<1, dim>              &slip,
                   const Tensor<1, dim>              &multiplier,
                   const std::vector<Tensor<1, dim>> &mean_slip,
                   const std::vector<double>         &mean_gap,
                   const double                       pressure,
                   const double                       kappa,
                   const double                       kappa_t,
                   const double                       length,
                   const Vector<double>              *iterate,
                   FullMatrix<double>                &matrix,
                   Vector<double>                    &rhs,
                   bool                              &sliding) const;

      /**
       * Uzawa's update of @p multipliers at the gap @p gap and slip @p slip
       * of the current iterate: the tractions the springs and the last
       * multipliers give there, Coulomb's cone applied.
       */
      void
      update(Multipliers          &multipliers,
             const double          gap,
             const Tensor<1, dim> &slip,
             const double          kappa,
             const double          kappa_t) const;

      double coefficient = 1e3;
      /// kappa_T / (E / h) of friction's sticking springs.
      double tangential_coefficient = 1e3;
      /// Pressure space = cells: one pressure per cell, from its mean gap.
      bool per_cell = true;

      /// Whether this assembly updates the multipliers (augmented, statuses
      /// settled).
      bool update_multipliers = false;
      /// Per cell with lips, the multipliers of each group (augmented).
      std::map<CellId, std::vector<Multipliers>> multipliers;

      /// A lip point's (or a cell's) status.
      enum Status : char
      {
        opened,
        sticking,
        slipping
      };
      /// Per cell with lips: the status of each pressure group (a point or
      /// the cell) as of the last assembly; at each lip point, the contact
      /// pressure and the whole traction on the lsn > 0 lip (p n + t_T).
      std::map<CellId, std::vector<char>>           statuses;
      std::map<CellId, std::vector<double>>         pressures;
      std::map<CellId, std::vector<Tensor<1, dim>>> tractions;
      /// Per cell with lips, the means of the last assembly.
      std::map<CellId, typename Interface<dim>::LipState> cell_states;
      /// Points whose status (open or closed) the last assembly changed,
      /// and where the first of them is.
      unsigned int n_changed = 0;
      /// Of those, the groups that switched between open, stick and slip
      /// (the rest: augmented groups whose multipliers wait for an update).
      unsigned int n_switched = 0;
      Point<dim>   first_changed;
      /// Of the last assembly, on this rank: the lips' length (area), that
      /// of the closed ones, the smallest and largest pressure where closed.
      double lip_measure = 0, closed_measure = 0, slip_measure = 0;
      double pressure_min = 0, pressure_max = 0;
      /// The smallest gap held at a closed group (the interpenetration).
      double gap_min = 0;
      /// Every lip point of the last assembly on this rank: where it is,
      /// its share of the lips, whether it is closed.
      struct LipPoint
      {
        Point<dim> x;
        double     ds;
        bool       closed;
      };
      std::vector<LipPoint> lip_points;

      std::unique_ptr<LipValues<dim>> lip_values;
    };



    /**
     * `augmented lagrangian`: the penalty's springs plus multipliers that
     * Uzawa's method updates at the Newton steps whose statuses have
     * settled (Alart and Curnier's
     * augmented Lagrangian; Code_Aster's ALGO_CONT = PENALISATION with
     * augmentation, Simo and Laursen 1992): the pressure is p = (lambda -
     * kappa g)_+ and the friction traction Coulomb's projection of lambda_T
     * - kappa_T s, and after each solve lambda and lambda_T take the
     * values p and t of the new iterate. At convergence g = 0 where closed
     * and the sticking lips do not slip: the constraint is exact whatever
     * the coefficient, which now sets only how fast Uzawa converges (its
     * error contracts by about 1 / (1 + coefficient) per step) and how
     * well the system is conditioned. The Newton loop's residual is kappa
     * g on the closed lips, so that `Nonlinear solver/Tolerance` is the
     * interpenetration's bound. Same pressure spaces and system as the
     * penalty's: symmetric without friction.
     */
    template <int dim>
    class AugmentedLagrangian : public Penalty<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;
    };
  } // namespace Contact
} // namespace xcrack

#endif
