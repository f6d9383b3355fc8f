#include <gelmpm/core/available_memory.h>

#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace GelMPM
{
  double
  available_memory()
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   line;
    while (std::getline(meminfo, line))
      if (line.rfind("MemAvailable:", 0) == 0)
        {
          std::istringstream in(line.substr(13));
          double             kilobytes = 0.;
          if (in >> kilobytes && kilobytes > 0.)
            return kilobytes * 1024.;
        }
    const double physical =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
    return physical > 0. ? physical : 0.;
  }
} // namespace GelMPM
