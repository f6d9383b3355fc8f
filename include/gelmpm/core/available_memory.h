#ifndef gelmpm_core_available_memory_h
#define gelmpm_core_available_memory_h

namespace GelMPM
{
  /**
   * The memory, in bytes, that this machine can give a new process now without swapping: Linux's
   * MemAvailable (/proc/meminfo), or the physical memory where that cannot be read; 0 if neither
   * can. The memory guards of the grid and of the points compare their estimates with a share of
   * it, before anything is allocated.
   */
  double
  available_memory();
} // namespace GelMPM

#endif
