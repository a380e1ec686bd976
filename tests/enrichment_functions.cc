// Requirement: every enriched shape function of the X-FEM elements is the
// hat function of its node times the function Enrichment::enrichment_function
// names for it (H or one of F1..F4): values and gradients, Q1 and Q2 (whose
// branch functions multiply Q1 hats), on a mesh with jump, branch and mixed
// cells. The Dirichlet fit relies on this correspondence.

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/xfem/enrichment.h>

#include <fstream>

using namespace dealii;
using namespace xcrack;

std::ofstream logfile("output");

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const unsigned int degree : {1u, 2u})
    {
      Triangulation<2> tria;
      GridGenerator::hyper_cube(tria, -1, 1);
      tria.refine_global(2);
      const SegmentCrack   crack(Point<2>(-2, 0.1),
                               Point<2>(0.05, 0.1),
                               false,
                               true);
      EnrichmentParameters parameters;
      parameters.tip_zone = EnrichmentParameters::TipZone::geometric;
      parameters.radius   = 0.3;
      LevelSetFields<2> fields(tria);
      fields.initialize({&crack});
      Enrichment<2> enrichment(1, degree, parameters);
      DoFHandler<2> dof_handler(tria);
      enrichment.set_fe_indices(dof_handler, fields);
      dof_handler.distribute_dofs(enrichment.get_fe_collection());

      const FE_Q<2>       linear(1), standard(degree);
      const Quadrature<2> points(
        std::vector<Point<2>>{Point<2>(0.3, 0.7), Point<2>(0.8, 0.2)});
      double       value_error = 0, gradient_error = 0;
      unsigned int n_jump = 0, n_branch = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const FiniteElement<2> &fe = cell->get_fe();
          FEValues<2>             fe_values(fe,
                                points,
                                update_values | update_gradients |
                                  update_quadrature_points);
          fe_values.reinit(cell);
          const double h = cell->extent_in_direction(0);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const Function<2> *f = enrichment.enrichment_function(cell, i);
              if (f == nullptr)
                continue;
              // The index of the DoF in its scalar base element.
              const auto &outer = fe.system_to_base_index(i);
              const auto &inner = fe.base_element(outer.first.first)
                                    .system_to_base_index(outer.second);
              const bool     branch = (inner.first.first == 2);
              const FE_Q<2> &hat    = (branch ? linear : standard);
              (branch ? n_branch : n_jump) += 1;
              const unsigned int c = fe.system_to_component_index(i).first;
              for (unsigned int q = 0; q < points.size(); ++q)
                {
                  const Point<2> &x = fe_values.quadrature_point(q);
                  const double    N =
                    hat.shape_value(inner.second, points.point(q));
                  const Tensor<1, 2> grad_N =
                    hat.shape_grad(inner.second, points.point(q)) / h;
                  value_error = std::max(value_error,
                                         std::abs(fe_values.shape_value(i, q) -
                                                  N * f->value(x)));
                  gradient_error =
                    std::max(gradient_error,
                             (fe_values.shape_grad_component(i, q, c) -
                              (grad_N * f->value(x) + N * f->gradient(x)))
                               .norm());
                }
            }
        }
      logfile << "Q" << degree << ": " << n_jump << " jump and " << n_branch
              << " branch shape functions checked; values match to 1e-13: "
              << (value_error < 1e-13 ? "yes" : "NO")
              << ", gradients match to 1e-12: "
              << (gradient_error < 1e-12 ? "yes" : "NO") << std::endl;
    }
}
