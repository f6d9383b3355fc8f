// How the B-spline tests report a check: one line "  <what> < <tolerance>: yes" (or "no  FAIL"),
// and the verdict of all checks so far in all_ok.
#ifndef gelmpm_tests_bspline_check_report_h
#define gelmpm_tests_bspline_check_report_h

#include <iostream>
#include <string>

namespace check_report
{
  inline bool all_ok = true;

  inline void
  report(const std::string &what, const double error, const double tolerance)
  {
    const bool ok = error < tolerance;
    all_ok &= ok;
    std::cout << "  " << what << " < " << tolerance << ": " << (ok ? "yes" : "no  FAIL")
              << std::endl;
  }
} // namespace check_report

#endif
