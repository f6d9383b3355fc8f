// gelmpm-swelling-1d: the finite-difference reference for constrained swelling (paper §4.1).
// Writes the thickness change against time and the stretch and chemical-potential profiles at
// chosen times as CSV; see doc/constrained_swelling.md for the equations and a convergence study.
#include <gelmpm/reference/constrained_swelling_1d.h>
#include <gelmpm/reference/tool_times.h>

#include <boost/program_options.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>


int
main(int argc, char **argv)
{
  namespace po = boost::program_options;
  GelMPM::ConstrainedSwelling1D::Parameters parameters;
  std::string                               times_text, directory;
  unsigned int                              n_samples;
  po::options_description                   options(
    "gelmpm-swelling-1d: finite-difference reference for constrained swelling (paper §4.1).\n"
                      "Lengths in h_0 (initial thickness), times in tau_d = h_0^2/D, mu in k_BT.\nOptions");
  options.add_options()("help", "this text")("cells",
                                             po::value(&parameters.n_cells)->default_value(800),
                                             "finite-difference cells")(
    "grading",
    po::value(&parameters.grading)->default_value(2.),
    "node grading towards the top, Y_i = 1 - (1 - i/n)^g")(
    "first-step",
    po::value(&parameters.first_step)->default_value(1e-9),
    "first time step")("growth",
                       po::value(&parameters.growth)->default_value(1.01),
                       "growth factor of consecutive time steps")(
    "chi",
    po::value(&parameters.chi)->default_value(0.1),
    "Flory-Huggins chi")("N-nu",
                         po::value(&parameters.N_nu)->default_value(7.299e-3),
                         "N nu")("lambda-0",
                                 po::value(&parameters.lambda_0)->default_value(1.2801),
                                 "initial isotropic stretch from the dry state")(
    "mu-top",
    po::value(&parameters.mu_top)->default_value(0.),
    "mu/k_BT on the top for t > 0")(
    "ramp",
    po::value(&parameters.ramp)->default_value(0.),
    "time over which mu on the top rises linearly from mu_0 (the initial state's) to mu-top; 0: a "
    "step at t = 0+")(
    "times",
    po::value(&times_text)->default_value("0.001197,0.008589,0.1281,0.4531,1.953,4.453,16.06,1713"),
    "comma-separated times of the profiles; the last one ends the run")(
    "samples",
    po::value(&n_samples)->default_value(400),
    "log-spaced times of the thickness curve, from 1e-6 to the end")(
    "output",
    po::value(&directory)->default_value("output/swelling_1d"),
    "output directory");

  try
    {
      po::variables_map vm;
      po::store(po::parse_command_line(argc, argv, options), vm);
      if (vm.count("help"))
        {
          std::cout << options << std::endl;
          return 0;
        }
      po::notify(vm);
      const std::vector<double> profile_times = GelMPM::parse_positive_times(times_text);
      const double              end = *std::max_element(profile_times.begin(), profile_times.end());

      std::set<double> times(profile_times.begin(), profile_times.end());
      for (unsigned int k = 0; k < n_samples; ++k)
        {
          const double t = 1e-6 * std::pow(end / 1e-6, (k + 1.) / n_samples);
          if (t < end)
            times.insert(t);
        }
      // A step ends where the ramp does (its kink).
      if (parameters.ramp > 0. && parameters.ramp < end)
        times.insert(parameters.ramp);

      GelMPM::ConstrainedSwelling1D reference(parameters);
      std::filesystem::create_directories(directory);
      std::ofstream thickness(directory + "/reference_thickness.csv");
      std::ofstream profiles(directory + "/reference_profiles.csv");
      thickness << "t_over_tau_d,delta_h_over_h0\n" << std::setprecision(12);
      profiles << "t_over_tau_d,Y_over_h0,lambda,mu_over_kT\n" << std::setprecision(12);
      for (const double t : times)
        {
          reference.advance_to(t);
          thickness << t << ',' << reference.thickness_change() << '\n';
          if (std::find(profile_times.begin(), profile_times.end(), t) != profile_times.end())
            {
              const auto mu = reference.chemical_potentials();
              for (unsigned int i = 0; i < mu.size(); ++i)
                profiles << t << ',' << reference.nodes()[i] << ',' << reference.stretches()[i]
                         << ',' << mu[i] << '\n';
              std::cout << "  t/tau_d = " << std::setw(10) << t
                        << "  Delta h/h_0 = " << std::setprecision(8)
                        << reference.thickness_change() << std::setprecision(6) << std::endl;
            }
        }
      const double lambda_eq = reference.stretch_at(parameters.mu_top);
      std::cout << "gelmpm-swelling-1d: " << reference.n_steps()
                << " steps; equilibrium Delta h/h_0 = " << std::setprecision(8) << lambda_eq - 1.
                << " (P_22 = 0 at mu = mu_top)\n"
                << "  results: " << directory << "/reference_thickness.csv, " << directory
                << "/reference_profiles.csv" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-swelling-1d: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}
