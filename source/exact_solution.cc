#include <deal.II/base/utilities.h>

#include <xcrack/exact_solution.h>
#include <xcrack/fracture/williams.h>
#include <xcrack/input_error.h>

#include <cmath>
#include <complex>

namespace xcrack
{
  namespace
  {
    /**
     * Westergaard's centre crack |x'| < a on y' = 0 (local axes) in an
     * infinite plate, remote stress (sigma'_xx, sigma'_yy, sigma'_xy):
     * Z_I = sigma'_yy z / sqrt(z^2 - a^2) (biaxial sigma'_yy), Z_II =
     * sigma'_xy z / sqrt(z^2 - a^2), and the uniform sigma'_xx - sigma'_yy
     * along the crack. sqrt(z^2 - a^2) = sqrt(z - a) sqrt(z + a) with
     * principal roots has its cut on the crack only. Displacements from
     * 2 mu u = ... (Tada, Paris and Irwin; Anderson, section A2.3).
     *
     * With @p closed lips (frictionless contact under a compressive
     * sigma'_yy) the crack transmits sigma'_yy: Z_I is replaced by the
     * uniform biaxial sigma'_yy it tends to at infinity, and only the
     * shear slides the lips (K_I = 0, K_II = sigma'_xy sqrt(pi a)). With
     * Coulomb friction mu on closed lips the whole crack slips if |sigma'_xy|
     * > mu |sigma'_yy| and sticks otherwise (both stresses are uniform
     * along it): Z_II carries the effective shear sigma'_xy - sign(
     * sigma'_xy) mu |sigma'_yy| (0 when stuck), the rest of sigma'_xy is
     * uniform, and K_II = (|sigma'_xy| - mu |sigma'_yy|)_+ sign(sigma'_xy)
     * sqrt(pi a) (Dolbow, Moes and Belytschko 2001, section 5.2; Liu and
     * Borja 2008).
     */
    template <int dim>
    class GriffithSolution : public Function<dim>
    {
    public:
      GriffithSolution(const Point<dim>          &centre,
                       const Tensor<1, 2>        &direction,
                       const double               a,
                       const std::vector<double> &remote,
                       const double               mu,
                       const double               kappa,
                       const bool                 closed,
                       const double               friction)
        : Function<dim>(dim)
        , centre(centre)
        , t(direction)
        , a(a)
        , mu(mu)
        , kappa(kappa)
        , closed(closed)
      {
        n[0] = -t[1];
        n[1] = t[0];
        // Remote stress in the crack's axes.
        const double sxx = remote[0], syy = remote[1], sxy = remote[2];
        const auto project = [&](const Tensor<1, 2> &u, const Tensor<1, 2> &v) {
          return u[0] * (sxx * v[0] + sxy * v[1]) +
                 u[1] * (sxy * v[0] + syy * v[1]);
        };
        s_tt   = project(t, t);
        s_nn   = project(n, n);
        s_tn   = project(t, n);
        s_open = (closed ? 0. : s_nn);
        if (closed)
          {
            const double excess = std::abs(s_tn) - friction * std::abs(s_nn);
            s_slide = (excess > 0 ? std::copysign(excess, s_tn) : 0.);
          }
        else
          s_slide = s_tn;
      }

      double
      value(const Point<dim> &p, const unsigned int component) const override
      {
        using C = std::complex<double>;
        const Tensor<1, 2> d({p[0] - centre[0], p[1] - centre[1]});
        const double       x = d * t, y = d * n;
        const C            z(x, y);
        const C            root = std::sqrt(z - a) * std::sqrt(z + a);
        const C            Z = z / root, Zbar = root;
        // Local displacements (u'_x, u'_y) times 2 mu.
        double ux = s_open * (0.5 * (kappa - 1) * Zbar.real() - y * Z.imag()) +
                    s_slide * (0.5 * (kappa + 1) * Zbar.imag() + y * Z.real());
        double uy = s_open * (0.5 * (kappa + 1) * Zbar.imag() - y * Z.real()) +
                    s_slide * (-0.5 * (kappa - 1) * Zbar.real() - y * Z.imag());
        // The shear that friction holds: uniform (2 mu eps'_xy).
        ux += (s_tn - s_slide) * y;
        uy += (s_tn - s_slide) * x;
        // Closed: the uniform biaxial sigma'_yy instead of Z_I's.
        if (closed)
          {
            ux += 0.5 * (kappa - 1) * s_nn * x;
            uy += 0.5 * (kappa - 1) * s_nn * y;
          }
        // Uniform sigma'_xx - sigma'_yy: eps_xx = (kappa + 1)/(8 mu) s,
        // eps_yy = (kappa - 3)/(8 mu) s, times 2 mu.
        const double s = s_tt - s_nn;
        ux += 0.25 * (kappa + 1) * s * x;
        uy += 0.25 * (kappa - 3) * s * y;
        ux /= 2 * mu;
        uy /= 2 * mu;
        return (component == 0 ? ux * t[0] + uy * n[0] : ux * t[1] + uy * n[1]);
      }

      /// The gradient in closed form (finite differences would straddle
      /// the lips at the points the tip rules put next to them).
      Tensor<1, dim>
      gradient(const Point<dim> &p, const unsigned int component) const override
      {
        using C = std::complex<double>;
        const Tensor<1, 2> d({p[0] - centre[0], p[1] - centre[1]});
        const double       y = d * n;
        const C            z(d * t, y);
        const C            root = std::sqrt(z - a) * std::sqrt(z + a);
        const C            Z = z / root, dZ = -a * a / (root * root * root);
        const double       k = kappa, s = s_tt - s_nn;
        // Local gradient G[i][j] = d u'_i / d x'_j, times 2 mu.
        Tensor<2, 2> G;
        G[0][0] = s_open * (0.5 * (k - 1) * Z.real() - y * dZ.imag()) +
                  s_slide * (0.5 * (k + 1) * Z.imag() + y * dZ.real()) +
                  0.25 * (k + 1) * s;
        G[0][1] =
          s_open * (-0.5 * (k - 1) * Z.imag() - Z.imag() - y * dZ.real()) +
          s_slide * (0.5 * (k + 1) * Z.real() + Z.real() - y * dZ.imag()) +
          (s_tn - s_slide);
        G[1][0] = s_open * (0.5 * (k + 1) * Z.imag() - y * dZ.real()) +
                  s_slide * (-0.5 * (k - 1) * Z.real() - y * dZ.imag()) +
                  (s_tn - s_slide);
        G[1][1] =
          s_open * (0.5 * (k + 1) * Z.real() - Z.real() + y * dZ.imag()) +
          s_slide * (0.5 * (k - 1) * Z.imag() - Z.imag() - y * dZ.real()) +
          0.25 * (k - 3) * s;
        if (closed)
          {
            G[0][0] += 0.5 * (k - 1) * s_nn;
            G[1][1] += 0.5 * (k - 1) * s_nn;
          }
        // Global: d u_c / d x_j = sum R[i][c] G[i][l] R[l][j], R rows t, n.
        const Tensor<1, 2> rows[2] = {t, n};
        Tensor<1, dim>     g;
        for (unsigned int j = 0; j < 2; ++j)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int l = 0; l < 2; ++l)
              g[j] += rows[i][component] * G[i][l] * rows[l][j] / (2 * mu);
        return g;
      }

    private:
      Point<dim>   centre;
      Tensor<1, 2> t, n;
      double       a, mu, kappa;
      bool         closed;
      double       s_tt = 0, s_nn = 0, s_tn = 0;
      /// sigma'_yy where Z_I carries it (open lips), else 0.
      double s_open = 0;
      /// sigma'_xy where Z_II carries it: all of it on open lips, the part
      /// friction does not hold on closed ones.
      double s_slide = 0;
    };
  } // namespace



  void
  ExactSolution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    {
      prm.declare_entry("Type",
                        "parsed",
                        Patterns::Selection("parsed|williams|griffith"),
                        "parsed: the expressions of Displacement (no exact "
                        "solution if empty); williams: the crack-tip field "
                        "of doc/benchmarks.md Case 1; griffith (2D): a centre "
                        "crack in an infinite plate under a remote stress "
                        "(Westergaard).");
      prm.declare_entry("Half-length",
                        "1",
                        Patterns::Double(0),
                        "griffith: half-length a of the crack, centred at "
                        "Tip along Tip direction.");
      prm.declare_entry("Remote stress",
                        "0, 1, 0",
                        Patterns::Anything(),
                        "griffith: sigma_xx, sigma_yy, sigma_xy at infinity "
                        "(global axes).");
      prm.declare_entry("Lips",
                        "open",
                        Patterns::Selection("open|closed"),
                        "griffith: open (traction-free lips), or closed: "
                        "frictionless lips in contact under a compressive "
                        "normal stress, which the crack transmits (K_I = 0; "
                        "the shear slides them).");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(0),
                        "griffith, Lips = closed: Coulomb's mu on the lips; "
                        "the crack slips under the shear mu times the normal "
                        "stress does not hold (K_II of that excess), or "
                        "sticks (K_II = 0).");
      prm.declare_entry("Displacement",
                        "",
                        Patterns::Anything(),
                        "parsed: exact displacement 'ux; uy[; uz]' if known; "
                        "L2_error and energy_error are then computed, "
                        "relative to the norms of the exact solution.");
      prm.declare_entry("Stress intensity factors",
                        "1, 0, 0",
                        Patterns::Anything(),
                        "williams: K_I, K_II, K_III.");
      prm.declare_entry("Tip",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "williams: the tip (in 3D a point of the straight "
                        "front).");
      prm.declare_entry("Tip direction",
                        "1, 0, 0",
                        Patterns::Anything(),
                        "williams: e1, pointing ahead of the tip.");
      prm.declare_entry("Crack normal",
                        "0, 1, 0",
                        Patterns::Anything(),
                        "williams: e2, pointing to the upper lip.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  std::shared_ptr<Function<dim>>
  ExactSolution::create(ParameterHandler        &prm,
                        const FunctionConstants &constants,
                        const Material          &material)
  {
    const std::string section = "Exact solution/";
    prm.enter_subsection("Exact solution");
    const std::string type         = prm.get("Type");
    const std::string displacement = prm.get("Displacement");
    const std::string sif          = prm.get("Stress intensity factors");
    const std::string tip          = prm.get("Tip");
    const std::string direction    = prm.get("Tip direction");
    const std::string normal       = prm.get("Crack normal");
    const double      half_length  = prm.get_double("Half-length");
    const std::string remote       = prm.get("Remote stress");
    const bool        closed       = (prm.get("Lips") == "closed");
    const double      friction     = prm.get_double("Friction coefficient");
    prm.leave_subsection();

    if (type == "griffith")
      {
        check_input(dim == 2, section + "Type = griffith is a 2D solution.");
        check_input(half_length > 0, section + "Half-length must be positive.");
        const std::vector<double> sigma =
          parse_numbers(remote, 3, section + "Remote stress");
        Tensor<1, 2> t = parse_vector<2>(direction, section + "Tip direction");
        check_input(t.norm() > 0, section + "Tip direction is zero.");
        t /= t.norm();
        // The normal stress on the crack must press closed lips together.
        const double s_nn = t[1] * t[1] * sigma[0] -
                            2 * t[0] * t[1] * sigma[2] + t[0] * t[0] * sigma[1];
        check_input(!closed || s_nn <= 0,
                    section +
                      "Lips = closed, but the remote stress pulls "
                      "the lips apart (normal stress " +
                      std::to_string(s_nn) + " > 0 on the crack).");
        return std::make_shared<GriffithSolution<dim>>(
          Point<dim>(parse_vector<dim>(tip, section + "Tip")),
          t,
          half_length,
          sigma,
          material.mu(),
          material.kappa(dim),
          closed,
          friction);
      }

    if (type == "parsed")
      {
        if (Utilities::trim(displacement).empty())
          return nullptr;
        return std::make_shared<ParsedVectorFunction<dim>>(
          displacement, dim, constants, section + "Displacement");
      }

    const std::vector<double> k =
      parse_numbers(sif, 3, section + "Stress intensity factors");
    WilliamsField field;
    field.k_I   = k[0];
    field.k_II  = k[1];
    field.k_III = k[2];
    field.mu    = material.mu();
    field.kappa = material.kappa(dim);

    const Point<dim>     p(parse_vector<dim>(tip, section + "Tip"));
    const Tensor<1, dim> e1 =
      parse_vector<dim>(direction, section + "Tip direction");
    const Tensor<1, dim> e2 =
      parse_vector<dim>(normal, section + "Crack normal");
    check_input(e1.norm() > 0 && e2.norm() > 0 &&
                  std::abs(e1 * e2) < 1e-10 * e1.norm() * e2.norm(),
                section + "Tip direction and " + section +
                  "Crack normal must be non-zero and orthogonal.");
    return std::make_shared<WilliamsSolution<dim>>(field, p, e1, e2);
  }



  template std::shared_ptr<Function<2>>
  ExactSolution::create<2>(ParameterHandler &,
                           const FunctionConstants &,
                           const Material &);
  template std::shared_ptr<Function<3>>
  ExactSolution::create<3>(ParameterHandler &,
                           const FunctionConstants &,
                           const Material &);
} // namespace xcrack
