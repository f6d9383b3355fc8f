#include <gelmpm/io/statistics_file.h>

#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  void
  StatisticsFile::open(const std::string &file_name, const std::vector<std::string> &columns)
  {
    file.open(file_name);
    if (!file)
      throw std::runtime_error("cannot write " + file_name);
    columns_ = columns;
    index.clear();
    for (unsigned int i = 0; i < columns.size(); ++i)
      index[columns[i]] = i;
    current.assign(columns.size(), "");
    for (unsigned int i = 0; i < columns.size(); ++i)
      file << (i ? "," : "") << columns[i];
    file << std::endl;
  }


  void
  StatisticsFile::set(const std::string &column, const double value)
  {
    const auto it = index.find(column);
    if (it == index.end())
      throw std::logic_error("statistics.csv has no column '" + column + "'");
    std::ostringstream text;
    text << std::setprecision(10) << value;
    current[it->second] = text.str();
  }


  void
  StatisticsFile::write_row()
  {
    for (unsigned int i = 0; i < current.size(); ++i)
      file << (i ? "," : "") << current[i];
    file << std::endl;
    rows_.push_back(current);
    current.assign(columns_.size(), "");
  }


  const std::vector<std::string> &
  StatisticsFile::columns() const
  {
    return columns_;
  }


  const std::vector<std::vector<std::string>> &
  StatisticsFile::rows() const
  {
    return rows_;
  }
} // namespace GelMPM
