#include <xcrack/output_file.h>
#include <xcrack/simulator.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  template <int dim>
  void
  SimulatorAccess<dim>::initialize_simulator(const Simulator<dim> &s)
  {
    simulator = &s;
  }



  template <int dim>
  const Simulator<dim> &
  SimulatorAccess<dim>::get_simulator() const
  {
    Assert(simulator, ExcMessage("initialize_simulator() was not called."));
    return *simulator;
  }



  template <int dim>
  MPI_Comm
  SimulatorAccess<dim>::get_mpi_communicator() const
  {
    return simulator->mpi_communicator;
  }



  template <int dim>
  const ConditionalOStream &
  SimulatorAccess<dim>::get_pcout() const
  {
    return simulator->pcout;
  }



  template <int dim>
  const FunctionConstants &
  SimulatorAccess<dim>::get_function_constants() const
  {
    return simulator->function_constants;
  }



  template <int dim>
  const parallel::distributed::Triangulation<dim> &
  SimulatorAccess<dim>::get_triangulation() const
  {
    return simulator->triangulation;
  }



  template <int dim>
  const DoFHandler<dim> &
  SimulatorAccess<dim>::get_dof_handler() const
  {
    return simulator->dof_handler;
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  SimulatorAccess<dim>::get_solution() const
  {
    return simulator->solution;
  }



  template <int dim>
  const Material &
  SimulatorAccess<dim>::get_material() const
  {
    return simulator->material;
  }



  template <int dim>
  const BoundaryConditions<dim> &
  SimulatorAccess<dim>::get_boundary_conditions() const
  {
    return simulator->boundary_conditions;
  }



  template <int dim>
  const LevelSetFields<dim> &
  SimulatorAccess<dim>::get_level_set_fields() const
  {
    return simulator->level_sets;
  }



  template <int dim>
  const std::vector<CrackSurface<dim>> &
  SimulatorAccess<dim>::get_crack_surfaces() const
  {
    return simulator->crack_surfaces;
  }



  template <int dim>
  const CrackSet<dim> &
  SimulatorAccess<dim>::get_initial_cracks() const
  {
    return simulator->cracks;
  }



  template <int dim>
  const Enrichment<dim> *
  SimulatorAccess<dim>::get_enrichment() const
  {
    return simulator->enrichment.get();
  }



  template <int dim>
  bool
  SimulatorAccess<dim>::lips_in_contact() const
  {
    return simulator->contact != nullptr;
  }



  template <int dim>
  const std::string &
  SimulatorAccess<dim>::get_output_directory() const
  {
    return simulator->run_parameters.output_directory;
  }



  template <int dim>
  void
  SimulatorAccess<dim>::write_output_file(
    const std::string                         &name,
    const std::function<void(std::ostream &)> &write) const
  {
    if (Utilities::MPI::this_mpi_process(simulator->mpi_communicator) != 0)
      return;
    write_file(simulator->run_parameters.output_directory + "/" + name, write);
    simulator->run_record->add_file(name);
  }



  template <int dim>
  unsigned int
  SimulatorAccess<dim>::get_step() const
  {
    return simulator->step;
  }



  template <int dim>
  double
  SimulatorAccess<dim>::get_cycles() const
  {
    return simulator->cycles;
  }



  template <int dim>
  const std::vector<FrontValues<dim>> &
  SimulatorAccess<dim>::get_front_values() const
  {
    return simulator->front_values;
  }



  template <int dim>
  const std::vector<FrontMove<dim>> &
  SimulatorAccess<dim>::get_front_moves() const
  {
    return simulator->front_moves;
  }



  template <int dim>
  const FractureParameters &
  SimulatorAccess<dim>::get_fracture_parameters() const
  {
    return simulator->fracture_parameters;
  }



  template <int dim>
  const KErrorCells &
  SimulatorAccess<dim>::get_k_error_cells() const
  {
    return simulator->k_error_cells;
  }



  template class SimulatorAccess<2>;
  template class SimulatorAccess<3>;
} // namespace xcrack
