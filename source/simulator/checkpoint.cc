#include <deal.II/base/mpi.h>

#include <xcrack/input_error.h>
#include <xcrack/run.h>
#include <xcrack/simulator.h>

#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/crc.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

namespace xcrack
{
  namespace
  {
    /// The version of the checkpoint format: a change of the state below
    /// must change it, so that an old checkpoint is refused, not misread.
    constexpr unsigned int checkpoint_version = 4;

    /// The CRC-32 and the size of the file @p path.
    std::pair<std::uint32_t, std::uintmax_t>
    checksum_of(const std::filesystem::path &path)
    {
      std::ifstream      in(path, std::ios::binary);
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 16);
      std::uintmax_t     size = 0;
      while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0)
        {
          crc.process_bytes(buffer.data(), in.gcount());
          size += in.gcount();
        }
      return {crc.checksum(), size};
    }

    /**
     * Write `checksums` in the checkpoint @p dir: a line per file of it
     * (name, size, CRC-32), so that a resume refuses a file changed or
     * damaged after it was written, by name, before anything reads it.
     */
    void
    write_checksums(const std::filesystem::path &dir)
    {
      std::vector<std::string> names;
      for (const auto &entry : std::filesystem::directory_iterator(dir))
        if (entry.is_regular_file())
          names.push_back(entry.path().filename().string());
      std::sort(names.begin(), names.end());
      std::ofstream out(dir / "checksums");
      for (const std::string &name : names)
        {
          const auto [crc, size] = checksum_of(dir / name);
          out << name << ' ' << size << ' ' << crc << '\n';
        }
      out.close();
      AssertThrow(out,
                  ExcMessage("Could not write the checkpoint in " +
                             dir.string() + "."));
    }

    /// InputError naming the first file of the checkpoint @p dir that is
    /// missing or differs from what its `checksums` say.
    void
    check_checksums(const std::filesystem::path &dir,
                    const std::string           &directory)
    {
      std::ifstream in(dir / "checksums");
      check_input(static_cast<bool>(in),
                  "--resume " + directory + ": " +
                    (dir / "checksums").string() +
                    " is missing: the checkpoint is incomplete or was "
                    "written by an older xcrack.");
      std::string    name;
      std::uintmax_t size = 0;
      std::uint32_t  crc  = 0;
      while (in >> name >> size >> crc)
        {
          const std::filesystem::path file = dir / name;
          check_input(std::filesystem::is_regular_file(file),
                      "--resume " + directory + ": " + file.string() +
                        " is missing: the checkpoint is damaged.");
          check_input(checksum_of(file) == std::make_pair(crc, size),
                      "--resume " + directory + ": " + file.string() +
                        " is not the file the run wrote (changed or "
                        "damaged since): the resume is refused. Start the "
                        "run anew to change its parameters.");
        }
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    // Written to checkpoint.tmp, then renamed: a run killed at any moment
    // leaves the previous checkpoint (checkpoint, or checkpoint.old during
    // the two renames) whole.
    namespace fs          = std::filesystem;
    const fs::path output = run_parameters.output_directory;
    const fs::path tmp    = output / "checkpoint.tmp";
    const fs::path old    = output / "checkpoint.old";
    const fs::path done   = output / "checkpoint";
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      {
        fs::remove_all(tmp);
        fs::create_directories(tmp);
      }
    MPI_Barrier(mpi_communicator);

    level_sets.prepare_for_serialization();
    triangulation.save((tmp / "mesh").string());
    if (root)
      {
        std::ofstream                   file(tmp / "state", std::ios::binary);
        boost::archive::binary_oarchive archive(file);
        const unsigned int              version = checkpoint_version;
        const unsigned int              d       = dim;
        const unsigned int              n_ranks =
          Utilities::MPI::n_mpi_processes(mpi_communicator);
        const unsigned int                    n_cracks  = cracks.size();
        const unsigned int                    next_step = step + 1;
        std::map<std::string, Plugins::State> plugin_states;
        for (const auto &[key, plugin] : plugins())
          plugin->save(plugin_states[key]);
        archive << version << d << n_ranks << n_cracks << next_step << cycles
                << cracks_moved << previous_moves << statistics << pvd_records
                << crack_records << plugin_states << k_error_cells.crown_inner
                << k_error_cells.crown_outer << k_error_cells.crown_cells;
        file.close();
        AssertThrow(file,
                    ExcMessage("Could not write the checkpoint in " +
                               tmp.string() + "."));
        // Every parameter, so that the run resumes from the checkpoint alone
        // (printed once per run: ParameterHandler takes 10 ms for it).
        std::ofstream parameters(tmp / "parameters.prm");
        parameters << parameters_text;
        parameters.close();
        AssertThrow(parameters,
                    ExcMessage("Could not write the checkpoint in " +
                               tmp.string() + "."));
      }
    // Every rank's part of the mesh is written.
    MPI_Barrier(mpi_communicator);
    if (root)
      {
        write_checksums(tmp);
        if (fs::exists(done))
          fs::rename(done, old);
        fs::rename(tmp, done);
        fs::remove_all(old);
      }
    MPI_Barrier(mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::read_checkpoint(const std::string &directory)
  {
    const std::string dir = checkpoint_of(directory);
    // The state first: a checkpoint of something else is refused before
    // the mesh is touched.
    std::ifstream                   file(dir + "/state", std::ios::binary);
    boost::archive::binary_iarchive archive(file);
    unsigned int version = 0, d = 0, n_ranks = 0, n_cracks = 0, next_step = 0;
    archive >> version >> d >> n_ranks >> n_cracks;
    check_input(version == checkpoint_version && d == dim &&
                  n_cracks == cracks.size(),
                "--resume " + directory +
                  ": the checkpoint was written by another version of xcrack "
                  "or for another problem.");
    std::map<std::string, Plugins::State> plugin_states;
    archive >> next_step >> cycles >> cracks_moved >> previous_moves >>
      statistics >> pvd_records >> crack_records >> plugin_states >>
      k_error_cells.crown_inner >> k_error_cells.crown_outer >>
      k_error_cells.crown_cells;
    step = next_step;
    for (const auto &[key, plugin] : plugins())
      if (const auto it = plugin_states.find(key); it != plugin_states.end())
        plugin->load(it->second);

    load_mesh(dir);
    if (n_ranks != Utilities::MPI::n_mpi_processes(mpi_communicator))
      pcout << "Warning: the checkpoint was written on " << n_ranks
            << " ranks; on another number the mesh is partitioned anew and "
               "the results may differ in the last digits."
            << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::load_mesh(const std::string &checkpoint)
  {
    // Indexed by cells that the load renumbers.
    k_error_cells.indicators.reinit(0);
    // load() wants the coarse mesh alone.
    triangulation.clear();
    mesh_description.create(triangulation, /*refine=*/false);
    triangulation.load(checkpoint + "/mesh");
    level_sets.deserialize(cracks.size());
  }



  template <int dim>
  std::map<std::string, Plugins::InterfaceBase *>
  Simulator<dim>::plugins() const
  {
    std::map<std::string, Plugins::InterfaceBase *> list;
    const auto add = [&](const std::string &system, Plugins::InterfaceBase *p) {
      if (p)
        list[system + "/" + p->plugin_name()] = p;
    };
    add("Linear solver", linear_solver.get());
    add("Mesh refinement", mesh_refinement.get());
    add("Contact", contact.get());
    for (const auto &[system, plugin] : propagation.plugins())
      add("Propagation/" + system, plugin);
    for (const auto &criterion : termination_criteria)
      add("Termination criteria", criterion.get());
    return list;
  }



  std::string
  checkpoint_of(const std::string &directory)
  {
    namespace fs = std::filesystem;
    for (const std::string name : {"checkpoint", "checkpoint.old"})
      {
        const fs::path dir = fs::path(directory) / name;
        if (fs::exists(dir / "state") && fs::exists(dir / "parameters.prm"))
          {
            check_checksums(dir, directory);
            return dir.string();
          }
      }
    throw InputError("--resume " + directory +
                     ": no checkpoint there (a directory 'checkpoint' with "
                     "the files 'state' and 'parameters.prm', written by a "
                     "propagation run after each step).");
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
