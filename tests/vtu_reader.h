// Reading a written .vtu file back as ParaView reads it, for the tests in tests/io and
// tests/output: tests/vtu_dump.py reads it with VTK's XML reader (vtkXMLUnstructuredGridReader)
// through Python's vtkmodules, which both Debian's python3-vtk9 and ParaView's python3-paraview
// provide (the two packages conflict, and VTK's C++ development package depends on the first, so
// linking VTK would keep ParaView off the machine). The test's CMakeLists.txt defines
// GELMPM_VTU_PYTHON (the interpreter) and GELMPM_VTU_DUMP (the script), after checking that the
// interpreter imports vtkmodules.vtkIOXML (tests/cmake/gelmpm_vtu_reader.cmake).
#ifndef GELMPM_TESTS_VTU_READER_H
#define GELMPM_TESTS_VTU_READER_H

#include <array>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace GelMPMTests
{
  /** One point-data array: n_tuples() tuples of n_components values each. */
  struct VtuArray
  {
    unsigned int        n_components = 1;
    std::vector<double> values;

    std::size_t
    n_tuples() const
    {
      return values.size() / n_components;
    }

    double
    operator()(const std::size_t tuple, const unsigned int component = 0) const
    {
      return values[tuple * n_components + component];
    }
  };

  /** Points, cells (the ids of their points) and point-data arrays of one .vtu file. */
  struct VtuFile
  {
    std::vector<std::array<double, 3>>    points;
    std::vector<std::vector<std::size_t>> cells;
    std::map<std::string, VtuArray>       point_data;

    /** The array of that name, or nullptr if the file has none. */
    const VtuArray *
    array(const std::string &name) const
    {
      const auto found = point_data.find(name);
      return found == point_data.end() ? nullptr : &found->second;
    }

    /** The array of that name; throws if the file has none. */
    const VtuArray &
    field(const std::string &name) const
    {
      if (const VtuArray *found = array(name))
        return *found;
      throw std::runtime_error("the .vtu file has no point-data array " + name);
    }
  };

  namespace internal
  {
    /** A number as Python prints it ("nan" and "inf" included, which operator>> refuses). */
    inline double
    vtu_number(std::istringstream &line)
    {
      std::string token;
      line >> token;
      char        *end   = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (token.empty() || *end != '\0')
        throw std::runtime_error("vtu_dump.py printed '" + token + "' where a number belongs");
      return value;
    }

    /** The whole standard output of command; throws if it cannot run or exits non-zero. */
    inline std::string
    output_of(const std::string &command)
    {
      FILE *pipe = popen(command.c_str(), "r");
      if (pipe == nullptr)
        throw std::runtime_error("cannot run " + command);
      std::string text;
      char        buffer[1 << 16];
      for (std::size_t n; (n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0;)
        text.append(buffer, n);
      if (pclose(pipe) != 0)
        throw std::runtime_error(command + " failed (its message is above)");
      return text;
    }

    /** The VtuFile printed by tests/vtu_dump.py (its docstring gives the form). */
    inline VtuFile
    parse_vtu_dump(const std::string &text)
    {
      std::istringstream in(text);
      std::string        line, word;
      VtuFile            file;
      const auto         count_after = [&](const char *keyword) {
        std::getline(in, line);
        std::istringstream header(line);
        std::size_t        n = 0;
        if (!(header >> word >> n) || word != keyword)
          throw std::runtime_error(std::string("vtu_dump.py: expected '") + keyword + " <n>'");
        return n;
      };
      file.points.resize(count_after("points"));
      for (auto &point : file.points)
        {
          std::getline(in, line);
          std::istringstream values(line);
          for (double &x : point)
            x = vtu_number(values);
        }
      file.cells.resize(count_after("cells"));
      for (auto &cell : file.cells)
        {
          std::getline(in, line);
          std::istringstream ids(line);
          std::size_t        n = 0;
          ids >> n;
          cell.resize(n);
          for (auto &id : cell)
            ids >> id;
        }
      while (std::getline(in, line) && !line.empty())
        {
          std::istringstream header(line);
          VtuArray           array;
          std::size_t        n_tuples = 0;
          std::string        name;
          if (!(header >> word >> array.n_components >> n_tuples) || word != "array")
            throw std::runtime_error("vtu_dump.py: expected 'array <components> <tuples> <name>'");
          std::getline(header >> std::ws, name);
          array.values.reserve(n_tuples * array.n_components);
          for (std::size_t i = 0; i < n_tuples; ++i)
            {
              std::getline(in, line);
              std::istringstream values(line);
              for (unsigned int c = 0; c < array.n_components; ++c)
                array.values.push_back(vtu_number(values));
            }
          file.point_data[name] = std::move(array);
        }
      return file;
    }
  } // namespace internal

  /**
   * The .vtu file file_name as VTK's XML reader reads it. Throws std::runtime_error if it cannot
   * be read (the script's message goes to stderr, and so into the test's output).
   */
  inline VtuFile
  read_vtu(const std::string &file_name)
  {
    return internal::parse_vtu_dump(internal::output_of(
      std::string("'") + GELMPM_VTU_PYTHON + "' '" + GELMPM_VTU_DUMP + "' '" + file_name + "'"));
  }
} // namespace GelMPMTests

#endif
