#include <deal.II/numerics/data_out.h>

#include <xcrack/output.h>
#include <xcrack/output_file.h>
#include <xcrack/simulator.h>

#include <fstream>
#include <iomanip>

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
    // zlib's fastest level: deal.II's default (best compression) made the
    // VTU files half of a 2D step (doc/performance.md, "The overhead of a
    // 2D step"); the files grow by 5 % to 8 %.
    DataOutBase::VtkFlags vtk_flags;
    vtk_flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(vtk_flags);
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
    const bool root = (Utilities::MPI::this_mpi_process(mpi_communicator) == 0);
    if (enrichment)
      {
        std::vector<std::string> names;
        for (unsigned int c = 0; c < crack_surfaces.size(); ++c)
          {
            names.push_back(
              "crack" +
              (cracks.size() > 1 ? std::to_string(c + 1) : std::string()) +
              "-" + key + ".vtu");
            crack_surfaces[c].write_vtu(dir + names.back(),
                                        dof_handler,
                                        solution,
                                        lip_fields);
            run_record->add_file(names.back());
          }
        // crack.pvd: every crack, one part each.
        if (root)
          {
            add_series_record(crack_records, names);
            write_file(dir + "crack.pvd", [&](std::ostream &pvd) {
              write_series(pvd, crack_records, cracks.size());
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
        add_series_record(pvd_records, {base + ".pvtu"});
        write_file(dir + "solution.pvd", [&](std::ostream &pvd) {
          write_series(pvd, pvd_records, 1);
        });
        for (const std::string &piece : pieces)
          run_record->add_file(piece);
        run_record->add_file(base + ".pvtu");
        run_record->add_file("solution.pvd");
      }
  }


  namespace
  {
    /// The step of the solve that wrote @p file (`solution-007.pvtu`,
    /// `crack2-000.01.vtu`): the digits after its first '-'.
    unsigned int
    step_of_file(const std::string &file)
    {
      const std::string::size_type dash = file.find('-');
      return std::stoul(file.substr(dash + 1));
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::add_series_record(
    std::vector<std::pair<double, std::string>> &records,
    const std::vector<std::string>              &files) const
  {
    // ParaView's time: the load cycles of a growth run (its step when it
    // counts no cycles), the mesh of a static one. A step solved on
    // several meshes keeps its last solve in the series, the one its
    // growth rests on (the others' files stay, listed in run.json).
    double time = statistics.get("mesh", statistics.n_rows() - 1);
    if (propagation.enabled())
      {
        time = (propagation.counts_cycles() ? cycles : double(step));
        while (!records.empty() && step_of_file(records.back().second) == step)
          records.pop_back();
      }
    for (const std::string &file : files)
      records.emplace_back(time, file);
  }



  template <int dim>
  void
  Simulator<dim>::write_series(
    std::ostream                                      &pvd,
    const std::vector<std::pair<double, std::string>> &records,
    const unsigned int                                 n_parts)
  {
    // deal.II's write_pvd_record() writes one part per time; a series of
    // several cracks has one part per crack at each time, in their order.
    pvd << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" "
           "ByteOrder=\"LittleEndian\">\n"
        << "  <Collection>\n"
        << std::setprecision(16);
    for (unsigned int i = 0; i < records.size(); ++i)
      pvd << "    <DataSet timestep=\"" << records[i].first
          << "\" group=\"\" part=\"" << i % n_parts << "\" file=\""
          << records[i].second << "\"/>\n";
    pvd << "  </Collection>\n</VTKFile>\n";
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
