#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <xcrack/crack/crack_geometry.h>
#include <xcrack/xfem/enrichment.h>
#include <fstream>
std::ofstream logfile("output");
using namespace dealii; using namespace xcrack;
int main(int argc, char**argv){
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (unsigned degree : {1u,2u}) {
  Triangulation<2> tria; GridGenerator::hyper_cube(tria,-1,1); tria.refine_global(2);
  SegmentCrack crack(Point<2>(-2,0.1), Point<2>(0.05,0.1), false, true);
  EnrichmentParameters prm; prm.tip_zone = EnrichmentParameters::TipZone::geometric; prm.radius = 10;
  Enrichment<2> e(crack, degree, prm);
  DoFHandler<2> dh(tria); e.set_fe_indices(dh); dh.distribute_dofs(e.get_fe_collection());
  FE_Q<2> q1(1), qp(degree);
  double maxerr=0, maxgrad=0;
  for (auto &cell : dh.active_cell_iterators()) {
    const auto &fe = cell->get_fe();
    Quadrature<2> quad(std::vector<Point<2>>{Point<2>(0.3,0.7), Point<2>(0.8,0.2)});
    FEValues<2> fv(fe, quad, update_values|update_gradients|update_quadrature_points);
    fv.reinit(cell);
    for (unsigned i=0;i<fe.n_dofs_per_cell();++i) {
      const Function<2>* f = e.enrichment_function(fe,i);
      if (!f) continue;
      const auto &idx = fe.system_to_base_index(i);
      const auto &inner = fe.base_element(idx.first.first).system_to_base_index(idx.second);
      const unsigned base = inner.first.first; const unsigned local = inner.second;
      const FE_Q<2> &basefe = (base==2 ? q1 : qp);
      for (unsigned q=0;q<2;++q){
        double expect = basefe.shape_value(local, quad.point(q)) * f->value(fv.quadrature_point(q));
        double got = fv.shape_value(i,q);
        maxerr = std::max(maxerr, std::abs(expect-got));
        // gradient: reference gradient mapped by the affine cell (size h)
        const double h = cell->extent_in_direction(0);
        Tensor<1,2> g_expect = basefe.shape_grad(local, quad.point(q)) / h * f->value(fv.quadrature_point(q)) + basefe.shape_value(local, quad.point(q)) * f->gradient(fv.quadrature_point(q));
        Tensor<1,2> g_got; for (unsigned d=0; d<2; ++d) g_got[d] = fv.shape_grad_component(i,q,fe.system_to_component_index(i).first)[d];
        maxgrad = std::max(maxgrad, (g_expect-g_got).norm());
      }
    }
  }
  logfile << "degree " << degree << " max mismatch " << maxerr << " grad " << maxgrad << std::endl;
  }
}
