#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>

#include <xcrack/fracture/displacement_jump.h>
#include <xcrack/fracture/front_curve.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/output_file.h>
#include <xcrack/simulator.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace xcrack
{
  template <int dim>
  void
  Simulator<dim>::compute_fracture_parameters(const LoadState<dim> &state,
                                              const bool            report)
  {
    TimerOutput::Scope t(*timer, "fracture");
    // The fronts of all cracks, numbered one after the other.
    std::vector<std::vector<FrontPoint<dim>>> fronts;
    for (const auto &surface : crack_surfaces)
      fronts.insert(fronts.end(),
                    surface.fronts().begin(),
                    surface.fronts().end());
    if (fronts.empty())
      return;

    // No shape values: the integrals and the estimate read gradients only
    // (FE_Enriched's tables for a tip rule of 750 points are large).
    hp::FEValues<dim> hp_fe_values(fe_collection,
                                   quadrature_collection,
                                   update_gradients | update_quadrature_points |
                                     update_JxW_values |
                                     update_inverse_jacobians);
    SpecialFEValues   special_values;
    const auto fe_values_of = [&](const auto &cell) -> const FEValues<dim> & {
      return reinit_fe_values(cell, hp_fe_values, special_values, degree + 1);
    };
    const auto lips_of = [&](const auto                  &cell,
                             std::vector<Point<dim>>     &points,
                             std::vector<double>         &weights,
                             std::vector<Tensor<1, dim>> &normals) {
      const auto rule = enrichment->lip_quadrature(cell);
      points          = rule.get_points();
      weights         = rule.get_weights();
      normals         = rule.get_normal_vectors();
    };
    const InteractionIntegral<dim> integral(fracture_parameters, material);
    const auto lip_pressure = scaled(state.loads->lip_pressure.get(), state);
    const auto body_force   = scaled(state.loads->body_force.get(), state);
    // Closed lips press on each other: their tractions load the lips.
    typename InteractionIntegral<dim>::LipTraction contact_traction;
    if (contact)
      contact_traction = [this](const auto &cell, const unsigned int k) {
        return contact->lip_traction(cell->id(), k);
      };
    const auto faces = boundary_face_of(state);
    front_values     = integral.compute(dof_handler,
                                    solution,
                                    fronts,
                                    fe_values_of,
                                    lip_pressure.get(),
                                    lips_of,
                                    body_force.get(),
                                    nullptr,
                                    contact_traction,
                                    faces);
    // Where the lips touch at the front, it is closed. Without contact, a
    // negative K_I says that the lips pass through each other there: the
    // point is closed too, and its K's are those of a body that does not
    // exist (Propagation does not grow it).
    for (FrontValues<dim> &v : front_values)
      v.closed =
        (contact ? contact->closed_fraction(v.point.position, v.r_inf) > 0.5 :
                   v.k_I < 0);
    if (!report)
      return;
    const bool estimate = fracture_parameters.error_estimate;
    if (estimate)
      estimate_k_errors(fronts, fe_values_of, lips_of, faces);

    // The cross-check by the displacement jumps over the crown.
    const MappingQ1<dim>        mapping;
    const GridTools::Cache<dim> cache(triangulation, mapping);
    for (auto &v : front_values)
      v.k_jump = displacement_jump_k(dof_handler,
                                     cache,
                                     solution,
                                     v.point,
                                     material,
                                     v.r_inf,
                                     v.r_sup,
                                     enrichment.get());
    flag_unreliable_points();
    const auto &values = front_values;
    // In a growth run the screen shows one line per step; the values are
    // in front_<step>.csv.
    ConditionalOStream out(std::cout, pcout.is_active() && detailed_screen);

    // The reference K at each point, if given.
    std::vector<Vector<double>> reference(values.size());
    const Function<dim>        *reference_function = nullptr;
    if constexpr (dim == 2)
      reference_function = fracture_parameters.reference_2d.get();
    else
      reference_function = fracture_parameters.reference_3d.get();
    if (reference_function)
      for (unsigned int i = 0; i < values.size(); ++i)
        {
          reference[i].reinit(dim);
          reference_function->vector_value(values[i].point.position,
                                           reference[i]);
        }
    const auto k_of = [](const FrontValues<dim> &v, const unsigned int m) {
      return (m == 0 ? v.k_I : m == 1 ? v.k_II : v.k_III);
    };
    constexpr unsigned int n_modes       = dim;
    const char            *mode_names[3] = {"K_I", "K_II", "K_III"};

    const auto warn_crown = [&](const FrontValues<dim> &v) {
      if (!v.crown_clear)
        out << "  Warning: the crown of " << (dim == 2 ? "tip " : "front ")
            << v.front + 1 << " (r_sup = " << v.r_sup
            << ") reaches the boundary or another "
            << (dim == 2 ? "tip" : "front")
            << "; its K and G are unreliable. Use smaller Fracture "
               "parameters/Crown radii or a finer mesh there."
            << std::endl;
    };

    // What closed points mean: with contact, lips that touch; without, a
    // negative K_I, lips that pass through each other.
    const auto closed_words = [&](const unsigned int n_closed,
                                  const unsigned int n) {
      std::ostringstream words;
      const std::string  where =
        (n == 1 ? "the tip" :
                  std::to_string(n_closed) + " of its " + std::to_string(n) +
                    " points");
      if (contact)
        words << "    the lips are closed at " << where << ": K_I counts as 0"
              << (n == 1 ? "" : " there");
      else
        words << "    K_I < 0 at " << where << ": the lips pass through each "
              << "other (Contact/Formulation = none); closed, "
              << (n == 1 ? "it does" : "they do") << " not grow";
      return words.str();
    };

    // On screen, K's are rounded to 1e-6 of the largest one: a K that
    // vanishes by symmetry then reads 0 rather than round-off that differs
    // between builds (the CSV files and the statistics keep every digit).
    if constexpr (dim == 2)
      for (unsigned int i = 0; i < values.size(); ++i)
        {
          const auto  &v = values[i];
          const double quantum =
            1e-6 * std::max({std::abs(v.k_I), std::abs(v.k_II), 1e-300});
          const auto rounded = [&](const double k) {
            return std::round(k / quantum) * quantum + 0.;
          };
          out << "  tip " << i + 1 << std::scientific << std::setprecision(6)
              << ": K_I = " << rounded(v.k_I) << ", K_II = " << rounded(v.k_II)
              << ", G = " << v.g << ", G_Irwin = " << v.g_irwin << std::endl
              << "    displacement jumps: ";
          if (std::isfinite(v.k_jump[0]))
            out << "K_I = " << rounded(v.k_jump[0])
                << ", K_II = " << rounded(v.k_jump[1]);
          else
            out << "none (the lips across the crown are too short or kinked)";
          out << std::defaultfloat << std::endl;
          if (estimate)
            out << "    estimated errors (K_exact - K): K_I " << std::scientific
                << std::setprecision(2) << rounded(v.k_error[0]) << ", K_II "
                << rounded(v.k_error[1]) << std::defaultfloat
                << (k_error_cells.crown_cells < 4 ?
                      " (unreliable: the mesh is too coarse for the dual "
                      "problem, its crown is less than 4 cells wide)" :
                      "")
                << std::endl;
          if (v.closed)
            out << closed_words(1, 1) << std::endl;
          warn_crown(v);
          const std::string suffix = "_" + std::to_string(i + 1);
          statistics.add_value("K_I" + suffix, v.k_I);
          statistics.add_value("K_II" + suffix, v.k_II);
          statistics.add_value("G" + suffix, v.g);
          // (Left empty where the lips do not reach across the crown.)
          if (std::isfinite(v.k_jump[0]))
            {
              statistics.add_value("K_I_jump" + suffix, v.k_jump[0]);
              statistics.add_value("K_II_jump" + suffix, v.k_jump[1]);
            }
          if (estimate)
            {
              statistics.add_value("K_I_estimate" + suffix, v.k_error[0]);
              statistics.add_value("K_II_estimate" + suffix, v.k_error[1]);
              if (i == 0)
                statistics.add_value("estimate_crown_cells",
                                     k_error_cells.crown_cells);
            }
        }
    else
      // Per front: the range and mean of each K over its nodes, and the
      // largest gap between G-theta and Irwin's G.
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          double       k_min[3] = {1e300, 1e300, 1e300};
          double       k_max[3] = {-1e300, -1e300, -1e300}, k_mean[3] = {};
          double       largest = 1e-300, irwin_gap = 0, g_max = 1e-300;
          double       estimate_max[3] = {0, 0, 0};
          unsigned int n               = 0;
          for (const auto &v : values)
            if (v.front == f)
              {
                for (unsigned int m = 0; m < 3; ++m)
                  {
                    k_min[m] = std::min(k_min[m], k_of(v, m));
                    k_max[m] = std::max(k_max[m], k_of(v, m));
                    k_mean[m] += k_of(v, m);
                    largest = std::max(largest, std::abs(k_of(v, m)));
                    estimate_max[m] =
                      std::max(estimate_max[m], std::abs(v.k_error[m]));
                  }
                irwin_gap = std::max(irwin_gap, std::abs(v.g - v.g_irwin));
                g_max     = std::max(g_max, std::abs(v.g));
                ++n;
              }
          const double quantum = 1e-6 * largest;
          const auto   rounded = [&](const double k) {
            return std::round(k / quantum) * quantum + 0.;
          };
          std::string basis;
          for (const auto &v : values)
            if (v.front == f)
              basis = v.basis;
          out << "  front " << f + 1 << ": " << n << " points (" << basis
              << "), " << std::scientific << std::setprecision(6);
          for (unsigned int m = 0; m < 3; ++m)
            {
              k_mean[m] /= n;
              out << (m > 0 ? "; " : "") << mode_names[m] << " in ["
                  << rounded(k_min[m]) << ", " << rounded(k_max[m]) << "]";
              const std::string suffix = "_" + std::to_string(f + 1);
              statistics.add_value(std::string(mode_names[m]) + "_min" + suffix,
                                   k_min[m]);
              statistics.add_value(std::string(mode_names[m]) + "_max" + suffix,
                                   k_max[m]);
              if (estimate)
                statistics.add_value(std::string(mode_names[m]) +
                                       "_estimate_max" + suffix,
                                     estimate_max[m]);
            }
          out << std::endl
              << "    |G - G_Irwin| / max G = " << std::setprecision(2)
              << std::round(irwin_gap / g_max * 1e4) * 1e-4 << std::defaultfloat
              << std::endl;
          if (estimate)
            {
              out << "    estimated errors (K_exact - K), largest along the "
                     "front: "
                  << std::scientific << std::setprecision(2);
              for (unsigned int m = 0; m < 3; ++m)
                out << (m > 0 ? ", " : "") << mode_names[m] << " "
                    << rounded(estimate_max[m]);
              out << std::defaultfloat
                  << (k_error_cells.crown_cells < 4 ?
                        " (unreliable: the mesh is too coarse for the dual "
                        "problem, its crown is less than 4 cells wide)" :
                        "")
                  << std::endl;
              if (f == 0)
                statistics.add_value("estimate_crown_cells",
                                     k_error_cells.crown_cells);
            }
          unsigned int n_closed = 0;
          for (const auto &v : values)
            n_closed += (v.front == f && v.closed);
          if (n_closed > 0)
            out << closed_words(n_closed, n) << std::endl;
          for (const auto &v : values)
            if (v.front == f && !v.crown_clear)
              {
                warn_crown(v);
                break;
              }
        }
    // Errors against the reference: relative to |K| where it does not
    // vanish (2D), or (3D) to the largest |K| of that mode along the front
    // (K_II and K_III vary in sign along a front under shear); absolute
    // where the reference is zero altogether.
    if (reference_function)
      {
        double error[3] = {0, 0, 0};
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            double scale = 0, overall = 0;
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                scale   = std::max(scale, std::abs(reference[i][m]));
                overall = std::max(overall, reference[i].l2_norm());
              }
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                double norm = (scale > 1e-12 * overall ? scale : overall);
                if (dim == 2)
                  norm = (std::abs(reference[i][m]) >
                              1e-12 * reference[i].l2_norm() ?
                            std::abs(reference[i][m]) :
                            reference[i].l2_norm());
                // A reference that vanishes altogether: the absolute error.
                if (norm == 0)
                  norm = 1;
                error[m] =
                  std::max(error[m],
                           std::abs(k_of(values[i], m) - reference[i][m]) /
                             norm);
              }
            statistics.add_value(std::string(mode_names[m]) + "_error",
                                 error[m]);
          }
        out << "  K errors against the reference (max over the "
            << (dim == 2 ? "tips" : "front")
            << ", to 1e-6): " << std::scientific << std::setprecision(3);
        for (unsigned int m = 0; m < n_modes; ++m)
          out << (m > 0 ? ", " : "") << mode_names[m] << " "
              << std::round(error[m] * 1e6) * 1e-6;
        out << std::defaultfloat << std::endl;
      }
  }



  template <int dim>
  void
  Simulator<dim>::flag_unreliable_points()
  {
    // The files say which points a run cannot trust (front_<key>.csv per
    // point, statistics.csv per solve): the screen's warnings alone are
    // lost once the run is over.
    unsigned long long       n_unreliable = 0;
    std::vector<std::string> reasons;
    for (const FrontValues<dim> &v : front_values)
      if (const std::string why = v.unreliable_reason(); !why.empty())
        {
          ++n_unreliable;
          if (std::find(reasons.begin(), reasons.end(), why) == reasons.end())
            reasons.push_back(why);
        }
    std::string text;
    for (const std::string &why : reasons)
      text += (text.empty() ? "" : "; ") + why;
    statistics.add_value("unreliable_points", n_unreliable);
    statistics.add_text("reason", text);
  }



  template <int dim>
  typename InteractionIntegral<dim>::BoundaryFaceOf
  Simulator<dim>::boundary_face_of(const LoadState<dim> &state) const
  {
    // The Neumann data of the state, scaled by its factor, shared by the
    // returned function's copies.
    auto tractions = std::make_shared<
      std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>>();
    for (const auto &[id, traction] : state.loads->neumann)
      (*tractions)[id] = scaled(traction.get(), state);
    return
      [this, tractions, &state](const auto &cell, const unsigned int face_no) {
        typename InteractionIntegral<dim>::BoundaryFace face;
        const types::boundary_id id = cell->face(face_no)->boundary_id();
        face.constrained            = state.loads->dirichlet.count(id) > 0;
        const auto traction         = tractions->find(id);
        if (traction != tractions->end())
          face.traction = traction->second.get();
        if (!face.constrained)
          face.rule = enrichment->boundary_face_quadrature(cell, face_no);
        return face;
      };
  }



  template <int dim>
  void
  Simulator<dim>::write_front_file(const std::string &key) const
  {
    write_file(run_parameters.output_directory + "/front_" + key + ".csv",
               [&](std::ostream &csv) { write_front_table(csv); });
    run_record->add_file("front_" + key + ".csv");
  }



  template <int dim>
  void
  Simulator<dim>::write_front_table(std::ostream &csv) const
  {
    csv << "index,s,x,y,z,K_I,K_II,K_III,G,G_Irwin,r_inf,r_sup,"
           "K_I_jump,K_II_jump,K_III_jump,front,closed";
    // The estimates of K_exact - K, when asked for.
    const bool errors = fracture_parameters.error_estimate;
    if (errors)
      csv << ",K_I_error,K_II_error,K_III_error";
    // The moves of a growth step: the K's at the minimum of the load
    // cycle, the equivalent K, its range, the rate, the kink angle
    // (radians) and the advance to the next step.
    const bool moves =
      (front_moves.size() == front_values.size() && !front_moves.empty());
    if (moves)
      csv << ",K_I_min,K_II_min,K_III_min,K_eq,delta_K,rate,angle,advance";
    // Last: whether the point's K (and its growth) cannot be trusted, and
    // why.
    csv << ",unreliable,reason";
    csv << '\n' << std::setprecision(10);
    for (unsigned int i = 0; i < front_values.size(); ++i)
      {
        const auto &v = front_values[i];
        csv << i << ',' << v.point.s << ',' << v.point.position[0] << ','
            << v.point.position[1] << ','
            << (dim == 3 ? v.point.position[dim - 1] : 0.) << ',' << v.k_I
            << ',' << v.k_II << ',' << v.k_III << ',' << v.g << ',' << v.g_irwin
            << ',' << v.r_inf << ',' << v.r_sup << ',';
        // No cross-check where the lips do not reach across the crown.
        if (std::isfinite(v.k_jump[0]))
          csv << v.k_jump[0] << ',' << v.k_jump[1] << ',' << v.k_jump[2];
        else
          csv << ",,";
        csv << ',' << v.front + 1 << ',' << v.closed;
        if (errors)
          csv << ',' << v.k_error[0] << ',' << v.k_error[1] << ','
              << v.k_error[2];
        if (moves)
          {
            // A rate that is not finite ended the run (check_rates()): its
            // field stays empty rather than holding inf or nan.
            const auto &m = front_moves[i];
            csv << ',' << m.k_minimum[0] << ',' << m.k_minimum[1] << ','
                << m.k_minimum[2] << ',' << m.k_eq << ',' << m.delta_k << ',';
            if (std::isfinite(m.rate))
              csv << m.rate;
            csv << ',' << m.angle << ',' << m.advance;
          }
        const std::string why = v.unreliable_reason();
        csv << ',' << !why.empty() << ',' << why << '\n';
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
