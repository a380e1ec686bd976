#ifndef xcrack_simulator_access_h
#define xcrack_simulator_access_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <xcrack/parsed_function.h>
#include <xcrack/plugins.h>

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;
  template <int dim>
  class LevelSetFields;
  template <int dim>
  class CrackSurface;
  template <int dim>
  class CrackSet;
  template <int dim>
  class Enrichment;
  template <int dim>
  struct FrontValues;
  template <int dim>
  struct FrontMove;
  class Material;
  struct FractureParameters;
  template <int dim>
  class BoundaryConditions;

  /**
   * What the K error estimate of a solve (`Fracture parameters/Error
   * estimate`) leaves for a refinement strategy: where the error sits, and
   * how well the mesh resolves the estimate's own dual problems.
   */
  struct KErrorCells
  {
    /// Each active cell's share of the estimate: per K node and mode, the
    /// |share| of that K's error, weighted by its estimate relative to the
    /// largest, summed (by active cell index, locally owned cells); empty
    /// until an estimate ran on the current mesh.
    Vector<float> indicators;
    /// The wide crown the estimate is applied to: these radii around
    /// every tip (after a growth step, around the moved tips).
    double crown_inner = 0, crown_outer = 0;
    /// Its width in its coarsest cells (under 4 the estimate is not to be
    /// trusted at all).
    double crown_cells = 0;
  };



  /**
   * Read access to the state of the Simulator for plugins (ASPECT's
   * SimulatorAccess): a plugin that derives from this class as well as from
   * its system's Interface gets the simulator before its parameters are
   * parsed, and reads the mesh, the solution, the cracks and the material
   * through the functions below. Nothing here lets a plugin change the
   * state: what it computes, it returns to the simulator.
   */
  template <int dim>
  class SimulatorAccess
  {
  public:
    virtual ~SimulatorAccess() = default;

    /// Called by create_plugin() before the plugin's parameters are parsed.
    void
    initialize_simulator(const Simulator<dim> &simulator);

  protected:
    /// The simulator itself (to create nested plugins with).
    const Simulator<dim> &
    get_simulator() const;

    MPI_Comm
    get_mpi_communicator() const;

    /// The screen stream of rank 0.
    const ConditionalOStream &
    get_pcout() const;

    /// The constants every expression of the parameter file may use.
    const FunctionConstants &
    get_function_constants() const;

    const parallel::distributed::Triangulation<dim> &
    get_triangulation() const;

    const DoFHandler<dim> &
    get_dof_handler() const;

    /// The displacement with ghost entries.
    const TrilinosWrappers::MPI::Vector &
    get_solution() const;

    const Material &
    get_material() const;

    /// The loads and supports of the parameter file.
    const BoundaryConditions<dim> &
    get_boundary_conditions() const;

    /// The cracks' level sets lsn, lst on the mesh.
    const LevelSetFields<dim> &
    get_level_set_fields() const;

    /// The cracks as the fields draw them (lips and ordered fronts).
    const std::vector<CrackSurface<dim>> &
    get_crack_surfaces() const;

    /// The shapes the cracks were given in the parameter file.
    const CrackSet<dim> &
    get_initial_cracks() const;

    /// The enrichment (null without a crack).
    const Enrichment<dim> *
    get_enrichment() const;

    /// Whether the crack lips carry contact (Contact/Formulation is not
    /// `none`): without it, lips may pass through each other.
    bool
    lips_in_contact() const;

    /// Where the run writes its files (`Output directory`).
    const std::string &
    get_output_directory() const;

    /// Write @p name in the output directory with @p write (rank 0, through
    /// write_file(): whole or not at all) and list it in run.json.
    void
    write_output_file(const std::string                         &name,
                      const std::function<void(std::ostream &)> &write) const;

    /// The propagation step of the current solve (0: the initial crack).
    unsigned int
    get_step() const;

    /// The load cycles N at the current step.
    double
    get_cycles() const;

    /// K and G at the points of every front (fronts numbered crack after
    /// crack) of the current solve.
    const std::vector<FrontValues<dim>> &
    get_front_values() const;

    /// The moves of those points computed for the next advance (empty
    /// before or without growth).
    const std::vector<FrontMove<dim>> &
    get_front_moves() const;

    const FractureParameters &
    get_fracture_parameters() const;

    /// Where the K error estimate of the last solve sits in the mesh.
    const KErrorCells &
    get_k_error_cells() const;

  private:
    const Simulator<dim> *simulator = nullptr;
  };



  /**
   * Create the plugin of @p InterfaceType named @p name, as every plugin
   * system does: give it the simulator (if it reads its state), let it
   * parse its parameters from the subsection @p prm is in, then call its
   * initialize(). @p entry names the selection entry for messages.
   */
  template <int dim, typename InterfaceType>
  std::unique_ptr<InterfaceType>
  create_plugin(const std::string    &name,
                const std::string    &entry,
                ParameterHandler     &prm,
                const Simulator<dim> &simulator)
  {
    std::unique_ptr<InterfaceType> plugin =
      Plugins::PluginList<InterfaceType>::create(name, entry);
    if (auto *access = dynamic_cast<SimulatorAccess<dim> *>(plugin.get()))
      access->initialize_simulator(simulator);
    plugin->parse_parameters(prm);
    plugin->initialize();
    return plugin;
  }
} // namespace xcrack

#endif
