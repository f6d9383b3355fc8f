#include <gelmpm/core/input_error.h>
#include <gelmpm/io/output_settings.h>

namespace GelMPM
{
  void
  OutputSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::FileName(Patterns::FileName::output),
                      "Directory for all results (created if missing; relative to the directory "
                      "gelmpm is started in). It receives the log, statistics.csv, "
                      "parameters.prm (the parameters as used, after --set) and the ParaView "
                      "files. A run first removes the files an earlier run wrote there (only the "
                      "names gelmpm writes: the particles, grid and mode series, statistics.csv, "
                      "stability.csv, events.csv, parameters.prm, original.prm, checkpoint.bin), "
                      "except with --resume, which continues them; it may not be the directory of "
                      "the scene file.");
    prm.declare_entry("Write particles",
                      "true",
                      Patterns::Bool(),
                      "Write the material points as .vtu files with a .pvd time series.");
    prm.declare_entry("Write grid",
                      "false",
                      Patterns::Bool(),
                      "Also write the background grid, at the same times as the particles, as "
                      "grid-NNNNN.vtu files with the series grid.pvd: per cell the "
                      "classification of the u and the mu space (u_cell_kind, mu_cell_kind: 0 "
                      "interior, 1 boundary, 2 outer) and the volume points it held "
                      "(n_volume_points); per vertex the displacement increment of the last "
                      "converged step (displacement_increment) and mu/(k_BT) (mu_over_kT) from the "
                      "extended B-spline fields, NaN on cells without material. Off by default: "
                      "it costs a pass over the points and an evaluation of the fields per step.");
    prm.declare_entry("Interval steps",
                      "1",
                      Patterns::Integer(0),
                      "Write ParaView output every this many converged time steps (0: only the "
                      "initial and the final state).");
    prm.declare_entry("Interval time",
                      "0",
                      Patterns::Double(0.),
                      "Also write ParaView output each time the simulated time passes a multiple "
                      "of this value, in units of tau_d (0: off).");
    prm.declare_entry("Test mode",
                      "false",
                      Patterns::Bool(),
                      "Keep the log free of timings, versions and paths so that it can be "
                      "compared with a stored reference output (used by the test suite).");
    prm.leave_subsection();
  }


  void
  OutputSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory       = prm.get("Directory");
    write_particles = prm.get_bool("Write particles");
    write_grid      = prm.get_bool("Write grid");
    interval_steps  = prm.get_integer("Interval steps");
    interval_time   = prm.get_double("Interval time");
    test_mode       = prm.get_bool("Test mode");
    prm.leave_subsection();
    require(!directory.empty(),
            "Output/Directory",
            "is empty",
            "name a directory for the results, e.g. 'output/my_scene'");
  }
} // namespace GelMPM
