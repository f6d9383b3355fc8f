#include <gelmpm/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  PvdSeries::PvdSeries(const std::string &directory, const std::string &name)
    : directory(directory)
    , name(name)
  {}


  std::string
  PvdSeries::next_file_name() const
  {
    std::ostringstream file_name;
    file_name << name << "-" << std::setw(5) << std::setfill('0') << series.size() << ".vtu";
    return file_name.str();
  }


  std::string
  PvdSeries::next_path() const
  {
    return directory + "/" + next_file_name();
  }


  void
  PvdSeries::add(const double time)
  {
    series.emplace_back(time, next_file_name());
    const std::string pvd = directory + "/" + name + ".pvd";
    {
      std::ofstream out(pvd + ".tmp");
      if (!out)
        throw std::runtime_error("cannot write " + pvd + ".tmp");
      dealii::DataOutBase::write_pvd_record(out, series);
    }
    std::rename((pvd + ".tmp").c_str(), pvd.c_str());
  }


  const std::vector<std::pair<double, std::string>> &
  PvdSeries::times_and_names() const
  {
    return series;
  }
} // namespace GelMPM
