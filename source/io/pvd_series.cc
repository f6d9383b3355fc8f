#include <gelmpm/core/collective.h>
#include <gelmpm/io/file_writing.h>
#include <gelmpm/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  PvdSeries::PvdSeries(const std::string &directory,
                       const std::string &name,
                       const MPI_Comm     communicator)
    : directory(directory)
    , name(name)
    , communicator(communicator)
  {}


  bool
  PvdSeries::parallel() const
  {
    return Collective::is_parallel(communicator);
  }


  std::string
  PvdSeries::next_file_name() const
  {
    std::ostringstream file_name;
    file_name << name << "-" << std::setw(5) << std::setfill('0') << series.size()
              << (parallel() ? ".pvtu" : ".vtu");
    return file_name.str();
  }


  std::string
  PvdSeries::next_path() const
  {
    return directory + "/" + next_file_name();
  }


  void
  PvdSeries::write(const double time, const std::function<void(std::ostream &)> &writer)
  {
    write_file(next_path(), writer);
    add(time);
  }


  void
  PvdSeries::write(
    const double                                                                 time,
    const std::function<void(std::ostream &)>                                   &writer,
    const std::function<void(std::ostream &, const std::vector<std::string> &)> &record_writer)
  {
    if (!parallel())
      {
        write(time, writer);
        return;
      }
    const unsigned int       n_ranks = dealii::Utilities::MPI::n_mpi_processes(communicator);
    const std::string        stem    = next_file_name().substr(0, next_file_name().size() - 5);
    std::vector<std::string> pieces;
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        std::ostringstream piece;
        piece << stem << "." << std::setw(4) << std::setfill('0') << r << ".vtu";
        pieces.push_back(piece.str());
      }
    std::string failure;
    try
      {
        write_file(directory + "/" + pieces[dealii::Utilities::MPI::this_mpi_process(communicator)],
                   writer);
        if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
          write_file(next_path(), [&](std::ostream &out) {
            record_writer(out, pieces);
          });
      }
    catch (const std::runtime_error &e)
      {
        failure = e.what();
      }
    // The record joins the series only when every piece is complete.
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
    add(time);
  }


  void
  PvdSeries::add(const double time)
  {
    auto listed = series;
    listed.emplace_back(time, next_file_name());
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      write_file(directory + "/" + name + ".pvd", [&](std::ostream &out) {
        dealii::DataOutBase::write_pvd_record(out, listed);
      });
    series = std::move(listed);
  }


  void
  PvdSeries::write_file(const std::string                         &path,
                        const std::function<void(std::ostream &)> &writer) const
  {
    const std::string partial = path + ".tmp";
    std::ofstream     out     = open_partial(partial, path);
    int               error   = 0;
    try
      {
        writer(out);
      }
    catch (const dealii::ExceptionBase &)
      {
        // deal.II's writers check the stream and throw a long library message; errno says why.
        error = errno != 0 ? errno : EIO;
      }
    commit_file(out, partial, path, error);
  }


  void
  PvdSeries::restore_files() const
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    const std::regex later(name + "-([0-9]{5})(\\.[0-9]{4})?\\.p?vtu(\\.tmp)?|" + name +
                           "\\.pvd\\.tmp");
    std::error_code  error;
    for (const auto &entry : std::filesystem::directory_iterator(directory, error))
      {
        std::smatch       match;
        const std::string file = entry.path().filename().string();
        if (std::regex_match(file, match, later) &&
            (match[1].length() == 0 || match[3].length() > 0 ||
             std::stoul(match[1].str()) >= series.size()))
          std::filesystem::remove(entry.path(), error);
      }
    write_file(directory + "/" + name + ".pvd", [&](std::ostream &out) {
      dealii::DataOutBase::write_pvd_record(out, series);
    });
  }


  const std::vector<std::pair<double, std::string>> &
  PvdSeries::times_and_names() const
  {
    return series;
  }
} // namespace GelMPM
