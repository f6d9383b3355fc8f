#include <gelmpm/io/file_writing.h>
#include <gelmpm/io/statistics_file.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  void
  StatisticsFile::set_columns(const std::string &file_name, const std::vector<std::string> &columns)
  {
    name     = file_name;
    complete = 0;
    columns_ = columns;
    index.clear();
    for (unsigned int i = 0; i < columns.size(); ++i)
      index[columns[i]] = i;
    current.assign(columns.size(), "");
    rows_.clear();
  }


  void
  StatisticsFile::write_here(const bool writes_file)
  {
    writes = writes_file;
  }


  void
  StatisticsFile::open(const std::string &file_name, const std::vector<std::string> &columns)
  {
    set_columns(file_name, columns);
    if (!writes)
      {
        append_line(columns);
        return;
      }
    errno = 0;
    file.open(file_name, std::ios::binary | std::ios::trunc);
    if (!file)
      throw std::runtime_error(write_failure(file_name, errno));
    append_line(columns);
  }


  void
  StatisticsFile::resume(const std::string              &file_name,
                         const std::vector<std::string> &columns,
                         const std::uintmax_t            size)
  {
    set_columns(file_name, columns);
    if (!writes)
      {
        complete = size;
        return;
      }
    std::error_code error;
    if (std::filesystem::file_size(file_name, error) < size || error)
      throw std::runtime_error("'" + file_name +
                               "' is shorter than when the checkpoint was written");
    std::filesystem::resize_file(file_name, size, error);
    if (error)
      throw std::runtime_error("cannot cut '" + file_name + "' back to the checkpoint (" +
                               error.message() + ")");
    // The rows so far, for rows(); the first line must be this run's header.
    std::ifstream in(file_name, std::ios::binary);
    std::string   line;
    for (bool header = true; std::getline(in, line); header = false)
      {
        std::vector<std::string> fields;
        std::stringstream        row(line);
        for (std::string cell; std::getline(row, cell, ',');)
          fields.push_back(cell);
        if (header && fields != columns)
          throw std::runtime_error("'" + file_name + "' has other columns than the resumed run");
        fields.resize(columns.size()); // a row's empty last fields
        if (!header)
          rows_.push_back(fields);
      }
    errno = 0;
    file.open(file_name, std::ios::binary | std::ios::app);
    if (!file)
      throw std::runtime_error(write_failure(file_name, errno));
    complete = size;
  }


  std::uintmax_t
  StatisticsFile::bytes() const
  {
    return complete;
  }


  void
  StatisticsFile::append_line(const std::vector<std::string> &fields)
  {
    std::string line;
    for (unsigned int i = 0; i < fields.size(); ++i)
      line += (i ? "," : "") + fields[i];
    line += '\n';
    if (!writes)
      {
        complete += line.size();
        return;
      }
    errno = 0;
    file.write(line.data(), line.size());
    file.flush();
    if (!file)
      {
        // A full disk may take part of the line: cut the file back to its last complete line.
        const int error = errno;
        file.close();
        std::error_code ignored;
        std::filesystem::resize_file(name, complete, ignored);
        throw std::runtime_error(write_failure(name, error));
      }
    complete += line.size();
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
  StatisticsFile::set(const std::string &column, const std::string &text)
  {
    const auto it = index.find(column);
    if (it == index.end())
      throw std::logic_error("statistics.csv has no column '" + column + "'");
    current[it->second] = text;
  }


  void
  StatisticsFile::write_row()
  {
    append_line(current);
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


  namespace
  {
    /** A field as a number; empty and text fields (e.g. the event of events.csv) as NaN. */
    double
    number_or_nan(const std::string &cell)
    {
      char        *end   = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      return (cell.empty() || end == cell.c_str() || *end != '\0') ? std::nan("") : value;
    }
  } // namespace


  std::map<std::string, std::vector<double>>
  read_statistics(const std::string &file_name)
  {
    std::ifstream in(file_name);
    if (!in)
      throw std::runtime_error("cannot read " + file_name);
    std::string                                line, cell;
    std::vector<std::string>                   names;
    std::map<std::string, std::vector<double>> columns;
    std::getline(in, line);
    for (std::stringstream header(line); std::getline(header, cell, ',');)
      names.push_back(cell);
    while (std::getline(in, line))
      {
        std::stringstream row(line);
        for (unsigned int c = 0; c < names.size(); ++c)
          {
            if (!std::getline(row, cell, ','))
              cell.clear();
            columns[names[c]].push_back(number_or_nan(cell));
          }
      }
    return columns;
  }
} // namespace GelMPM
