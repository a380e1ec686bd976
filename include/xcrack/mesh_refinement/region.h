#ifndef xcrack_mesh_refinement_region_h
#define xcrack_mesh_refinement_region_h

#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/parsed_function.h>
#include <xcrack/simulator_access.h>

#include <memory>

namespace xcrack
{
  namespace MeshRefinement
  {
    /**
     * `region`: every cell whose centre satisfies `Region` (an expression of
     * x, y, z, positive inside; `subsection Region`) is refined, the way one
     * refines around a hole or a load by hand.
     */
    template <int dim>
    class Region : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      mark(parallel::distributed::Triangulation<dim> &triangulation)
        const override;

    private:
      std::unique_ptr<ParsedVectorFunction<dim>> region;
    };
  } // namespace MeshRefinement
} // namespace xcrack

#endif
