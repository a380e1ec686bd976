#include <deal.II/numerics/data_out.h>

#include <xcrack/output.h>
#include <xcrack/output_file.h>
#include <xcrack/simulator.h>

#include <fstream>

namespace xcrack
{
  template <int dim>
  void
  Simulator<dim>::output_results(const std::string &key)
  {
    TimerOutput::Scope t(*timer, "output");

    const StressPostprocessor<dim> stress(material);
    DataOut<dim>                   data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(
      solution,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(solution, stress);
    Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = triangulation.locally_owned_subdomain();
    data_out.add_data_vector(subdomain, "subdomain");
    // Which functions each cell carries (0 plain, 1 jump, 2 branch, 3 both)
    // and what the crack does to it (0 nothing, 1 splits it, 2 front in it,
    // 3 front within a diameter): what a user checks first when an enriched
    // run looks wrong.
    Vector<float> enrichment_index(triangulation.n_active_cells());
    Vector<float> crack_category(triangulation.n_active_cells());
    if (enrichment)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            enrichment_index[cell->active_cell_index()] =
              cell->active_fe_index();
            crack_category[cell->active_cell_index()] =
              enrichment->cell_category(cell);
          }
    if (enrichment)
      {
        data_out.add_data_vector(enrichment_index, "enrichment");
        data_out.add_data_vector(crack_category, "crack_cell");
      }
    for (unsigned int i = 0; i < cracks.size(); ++i)
      {
        const std::string suffix =
          (cracks.size() > 1 ? std::to_string(i + 1) : "");
        data_out.add_data_vector(level_sets.get_dof_handler(),
                                 level_sets.lsn(i),
                                 "lsn" + suffix);
        data_out.add_data_vector(level_sets.get_dof_handler(),
                                 level_sets.lst(i),
                                 "lst" + suffix);
      }
    data_out.build_patches(degree);
    // crack-<key>.vtu for one crack, crack<i>-<key>.vtu for several, and
    // crack.pvd, the series of the first crack (ParaView shows it grow).
    const std::string dir = run_parameters.output_directory + "/";
    // With contact the lips show what is shut: pressure, the gap the
    // formulation holds (the corners' gap varies about it), traction (with
    // friction's), and the closed and slipping fractions of each cell.
    std::vector<typename CrackSurface<dim>::LipField> lip_fields;
    if (contact)
      {
        const auto state = [this](const CellId &cell) {
          return contact->lip_state(cell);
        };
        lip_fields.push_back({"contact_pressure", 1, [state](const CellId &c) {
                                return std::vector<double>{state(c).pressure};
                              }});
        lip_fields.push_back({"contact_gap", 1, [state](const CellId &c) {
                                return std::vector<double>{state(c).gap};
                              }});
        lip_fields.push_back(
          {"contact_traction", 3, [state](const CellId &c) {
             const Tensor<1, dim> t = state(c).traction;
             return std::vector<double>{t[0], t[1], dim == 3 ? t[dim - 1] : 0.};
           }});
        lip_fields.push_back({"contact_closed", 1, [state](const CellId &c) {
                                return std::vector<double>{state(c).closed};
                              }});
        if (contact->friction > 0)
          lip_fields.push_back(
            {"contact_slipping", 1, [state](const CellId &c) {
               return std::vector<double>{state(c).slipping};
             }});
      }
    if (enrichment)
      for (unsigned int c = 0; c < crack_surfaces.size(); ++c)
        {
          const std::string name =
            "crack" +
            (cracks.size() > 1 ? std::to_string(c + 1) : std::string()) + "-" +
            key + ".vtu";
          crack_surfaces[c].write_vtu(dir + name,
                                      dof_handler,
                                      solution,
                                      lip_fields);
          run_record->add_file(name);
          if (c == 0 && Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
            {
              crack_records.emplace_back(statistics.n_rows() - 1, name);
              write_file(dir + "crack.pvd", [&](std::ostream &pvd) {
                DataOutBase::write_pvd_record(pvd, crack_records);
              });
              run_record->add_file("crack.pvd");
            }
        }

    const std::string  base = "solution-" + key;
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    write_file(dir + base + "." + Utilities::int_to_string(rank, 4) + ".vtu",
               [&](std::ostream &out) { data_out.write_vtu(out); });
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(base + "." + Utilities::int_to_string(r, 4) +
                           ".vtu");
        write_file(dir + base + ".pvtu", [&](std::ostream &pvtu) {
          data_out.write_pvtu_record(pvtu, pieces);
        });
        // The time of a record: the index of the solve (the row of
        // statistics.csv), which increases over meshes and steps alike.
        pvd_records.emplace_back(statistics.n_rows() - 1, base + ".pvtu");
        write_file(dir + "solution.pvd", [&](std::ostream &pvd) {
          DataOutBase::write_pvd_record(pvd, pvd_records);
        });
        for (const std::string &piece : pieces)
          run_record->add_file(piece);
        run_record->add_file(base + ".pvtu");
        run_record->add_file("solution.pvd");
      }
  }


  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
