#include <gelmpm/core/input_error.h>
#include <gelmpm/core/unit_tables.h>
#include <gelmpm/core/units.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace GelMPM
{
  namespace
  {
    using namespace UnitTables;

    /** The molar gas constant R = N_A k_B, J/(mol K) (exact in the SI since 2019). */
    constexpr double gas_constant = 8.314462618;

    struct UnitName
    {
      const char *name;
      double      si; // the unit in SI units
    };

    const std::vector<UnitName> length_units =
      {{"m", 1.}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"µm", 1e-6}, {"nm", 1e-9}};
    const std::vector<UnitName> time_units   = {{"s", 1.},
                                                {"ms", 1e-3},
                                                {"min", 60.},
                                                {"h", 3600.},
                                                {"d", 86400.}};
    const std::vector<UnitName> stress_units = {{"Pa", 1.},
                                                {"kPa", 1e3},
                                                {"MPa", 1e6},
                                                {"GPa", 1e9}};
    const std::vector<UnitName> force_units =
      {{"N", 1.}, {"kN", 1e3}, {"mN", 1e-3}, {"uN", 1e-6}, {"µN", 1e-6}, {"nN", 1e-9}};
    // The chemical potential per mole in J/mol is k_BT times R T: the factor is R T / si.
    const std::vector<UnitName> mu_units = {{"kT", 0.}, {"J/mol", 1.}, {"kJ/mol", 1e3}};


    std::vector<std::string>
    split_path(const std::string &path)
    {
      std::vector<std::string> parts;
      std::string              part;
      for (const char c : path)
        if (c == '/')
          {
            parts.push_back(part);
            part.clear();
          }
        else
          part += c;
      parts.push_back(part);
      return parts;
    }


    /** The rule of @p path, or nullptr. Entries below a piece, region or obstacle match '*'. */
    const EntryRule *
    rule_of(const std::string &path)
    {
      const auto parts = split_path(path);
      for (const auto &rule : entry_rules())
        {
          const auto pattern = split_path(rule.path);
          if (pattern.size() != parts.size())
            continue;
          bool match = true;
          for (std::size_t k = 0; k < parts.size() && match; ++k)
            match = pattern[k] == "*" || pattern[k] == parts[k];
          if (match)
            return &rule;
        }
      return nullptr;
    }


    /** The shortest text that reads back as @p x exactly. */
    std::string
    shortest_text(const double x)
    {
      for (int digits = 6; digits <= 17; ++digits)
        {
          std::ostringstream text;
          text << std::setprecision(digits) << x;
          if (std::strtod(text.str().c_str(), nullptr) == x)
            return text.str();
        }
      std::ostringstream text;
      text << std::setprecision(17) << x;
      return text.str();
    }


    /** @p x to six digits, for the log. */
    std::string
    shown(const double x)
    {
      std::ostringstream text;
      text << std::setprecision(6) << x;
      return text.str();
    }


    /** @p text as a number, if it is one entirely. */
    bool
    read_number(const std::string &text, double &x)
    {
      const std::string trimmed = dealii::Utilities::trim(text);
      if (trimmed.empty())
        return false;
      char *end = nullptr;
      x         = std::strtod(trimmed.c_str(), &end);
      return end == trimmed.c_str() + trimmed.size() && std::isfinite(x);
    }


    /** @p text with every number in it (separated by ',', ':', ';' or spaces) mapped by @p f. */
    std::string
    map_numbers(const std::string &text, const std::function<double(double)> &f)
    {
      std::string result, token;
      const auto  flush = [&]() {
        double x;
        result += read_number(token, x) && f(x) != x ? shortest_text(f(x)) : token;
        token.clear();
      };
      for (const char c : text)
        if (c == ',' || c == ':' || c == ';' || std::isspace(static_cast<unsigned char>(c)))
          {
            flush();
            result += c;
          }
        else
          token += c;
      flush();
      return result;
    }


    /**
     * @p expression with each of the variables in @p replacements (not a function's name: not
     * followed by '(') replaced by its text; numbers and other names are kept.
     */
    std::string
    substitute(const std::string                        &expression,
               const std::map<std::string, std::string> &replacements)
    {
      std::string result;
      for (std::size_t k = 0; k < expression.size();)
        {
          const char c = expression[k];
          if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
            {
              std::size_t end = k;
              while (end < expression.size() &&
                     (std::isalnum(static_cast<unsigned char>(expression[end])) ||
                      expression[end] == '_'))
                ++end;
              const std::string name = expression.substr(k, end - k);
              std::size_t       next = end;
              while (next < expression.size() &&
                     std::isspace(static_cast<unsigned char>(expression[next])))
                ++next;
              const auto found = replacements.find(name);
              const bool call  = next < expression.size() && expression[next] == '(';
              result += (found != replacements.end() && !call) ? found->second : name;
              k = end;
            }
          else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
            {
              // A number, with its exponent ('1e-3' holds no variable 'e').
              std::size_t end = k;
              while (end < expression.size() &&
                     (std::isdigit(static_cast<unsigned char>(expression[end])) ||
                      expression[end] == '.'))
                ++end;
              if (end < expression.size() && (expression[end] == 'e' || expression[end] == 'E'))
                {
                  std::size_t exponent = end + 1;
                  if (exponent < expression.size() &&
                      (expression[exponent] == '+' || expression[exponent] == '-'))
                    ++exponent;
                  if (exponent < expression.size() &&
                      std::isdigit(static_cast<unsigned char>(expression[exponent])))
                    {
                      end = exponent;
                      while (end < expression.size() &&
                             std::isdigit(static_cast<unsigned char>(expression[end])))
                        ++end;
                    }
                }
              result += expression.substr(k, end - k);
              k = end;
            }
          else
            {
              result += c;
              ++k;
            }
        }
      return result;
    }


    /** Mangled names of deal.II's JSON listing ("_20" for a space) as they are declared. */
    std::string
    demangle(const std::string &name)
    {
      std::string result;
      for (std::size_t k = 0; k < name.size(); ++k)
        if (name[k] == '_' && k + 2 < name.size() &&
            std::isxdigit(static_cast<unsigned char>(name[k + 1])) &&
            std::isxdigit(static_cast<unsigned char>(name[k + 2])))
          {
            result += static_cast<char>(std::stoi(name.substr(k + 1, 2), nullptr, 16));
            k += 2;
          }
        else
          result += name[k];
      return result;
    }


    struct Entry
    {
      std::string path, value, default_value;
    };

    /** Every entry of @p prm with its value and default, in the order of the listing. */
    std::vector<Entry>
    all_entries(const dealii::ParameterHandler &prm)
    {
      std::stringstream json;
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      std::vector<Entry>                                                                  entries;
      const std::function<void(const boost::property_tree::ptree &, const std::string &)> walk =
        [&](const boost::property_tree::ptree &node, const std::string &path) {
          for (const auto &[name, child] : node)
            {
              const std::string child_path = path + demangle(name);
              if (const auto value = child.get_optional<std::string>("value"))
                entries.push_back(
                  {child_path, *value, child.get<std::string>("default_value", *value)});
              else
                walk(child, child_path + "/");
            }
        };
      walk(tree, "");
      return entries;
    }


    std::string
    get_entry(const dealii::ParameterHandler &prm, const std::string &path)
    {
      auto parts = split_path(path);
      return prm.get(std::vector<std::string>(parts.begin(), parts.end() - 1), parts.back());
    }


    void
    set_entry(dealii::ParameterHandler &prm, const std::string &path, const std::string &value)
    {
      const auto parts = split_path(path);
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        prm.enter_subsection(parts[k]);
      prm.set(parts.back(), value);
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        prm.leave_subsection();
    }


    std::string
    names_of(const std::vector<UnitName> &table)
    {
      std::string names;
      for (const auto &unit : table)
        names += (names.empty() ? "" : ", ") + std::string(unit.name);
      return names;
    }


    /** The SI value of the unit @p name of @p table; InputError naming @p entry if unknown. */
    double
    unit_in_si(const std::vector<UnitName> &table,
               const std::string           &name,
               const std::string           &entry)
    {
      for (const auto &unit : table)
        if (name == unit.name)
          return unit.si;
      throw InputError(entry,
                       name.empty() ? "is empty, but the scene names laboratory units"
                                    : "is '" + name + "', a unit GelMPM does not know",
                       "give one of " + names_of(table));
    }


    /** A number of the section Units that must be positive when it is used. */
    double
    positive(const dealii::ParameterHandler &prm,
             const std::string              &entry,
             const std::string              &problem,
             const std::string              &fix)
    {
      const double x = prm.get_double(entry);
      require(x > 0., "Units/" + entry, "is " + shortest_text(x) + ": " + problem, fix);
      return x;
    }


    /** The doc line of --print-parameters for @p rule. */
    std::string
    rule_description(const EntryRule *rule)
    {
      if (rule == nullptr)
        return "NOT IN THE TABLE of source/core/units.cc: not converted; in a laboratory scene "
               "only its default is accepted";
      std::map<Quantity, std::string> names = {
        {Quantity::length, "a length (Length unit)"},
        {Quantity::time, "a time (Time unit)"},
        {Quantity::rate, "a rate (per Time unit)"},
        {Quantity::stress, "a stress (Stress unit)"},
        {Quantity::chemical_potential, "a chemical potential (Chemical potential unit)"},
        {Quantity::diffusivity, "a diffusivity (Length unit^2/Time unit)"},
        {Quantity::velocity, "a solvent volume flux per area (Length unit/Time unit)"}};
      switch (rule->form)
        {
          case Form::function:
            return "a function of x, y (, z) in the Length unit and t in the Time unit, its "
                   "value " +
                   names[rule->quantity] + "; converted by wrapping";
          case Form::selector:
            return "an expression in x, y (, z) in the Length unit (normals as they are); "
                   "converted by wrapping";
          case Form::level_set:
            return "an expression in x, y (, z) in the Length unit, only its sign matters; "
                   "converted by wrapping";
          case Form::moving_level_set:
            return "an expression in x, y (, z) in the Length unit and t in the Time unit, only "
                   "its sign matters; converted by wrapping";
          case Form::holes:
            return "centres and radii are lengths (Length unit), an axis direction is not "
                   "converted";
          default:
            break;
        }
      switch (rule->quantity)
        {
          case Quantity::none:
            return "not converted (no physical dimension)";
          case Quantity::constants:
            return "not converted: constants of the expression, in the units the expression "
                   "is written in";
          case Quantity::refused:
            return "cannot be converted (a mesh's coordinates): refused in a laboratory scene";
          default:
            return names[rule->quantity];
        }
    }


    /** The fields of one line of a .csv file written by StatisticsFile (no quoting). */
    std::vector<std::string>
    csv_fields(const std::string &line)
    {
      std::vector<std::string> fields(1);
      for (const char c : line)
        if (c == ',')
          fields.emplace_back();
        else
          fields.back() += c;
      return fields;
    }
  } // namespace


  void
  Units::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Selection;
    prm.enter_subsection("Units");
    prm.declare_entry(
      "Scene values",
      "normalised",
      Selection("normalised|laboratory"),
      "normalised: the scene's numbers are in the normalised units (lengths in units of a "
      "length of the scene's choice, times in tau_d, stresses in units of 'Material/Shear "
      "modulus' G, chemical potentials in k_BT). laboratory: they are in the units named "
      "below, and the run converts them to normalised values before it reads them: lengths "
      "by 'Time stepping/Characteristic length' L, times by tau_d = L^2/D (D = "
      "'Material/Diffusivity'), stresses by G, chemical potentials by k_BT (each entry's "
      "documentation says how it is converted, 'Laboratory units'). The log (and --check) "
      "prints each converted entry, laboratory value -> normalised value; --print-parameters "
      "and parameters.prm show the normalised values, with this entry 'normalised' and the "
      "scales below filled in. See doc/own_scenes.md, 'Laboratory units'.");
    prm.declare_entry("Length unit",
                      "",
                      dealii::Patterns::Anything(),
                      "The laboratory unit of lengths: m, cm, mm, um (or µm), nm. Empty: no "
                      "laboratory units (then the other names are not used).");
    prm.declare_entry("Time unit", "", dealii::Patterns::Anything(), "s, ms, min, h or d.");
    prm.declare_entry("Stress unit", "", dealii::Patterns::Anything(), "Pa, kPa, MPa or GPa.");
    prm.declare_entry("Force unit",
                      "",
                      dealii::Patterns::Anything(),
                      "The unit of the forces of statistics_units.csv: N, kN, mN, uN (or µN), "
                      "nN; per 'Length unit' of thickness in plane strain. Empty: forces in "
                      "'Stress unit' times 'Length unit'^2 (plane strain: ^1).");
    prm.declare_entry("Chemical potential unit",
                      "kT",
                      dealii::Patterns::Anything(),
                      "kT: chemical potentials in units of k_BT (as normalised); J/mol or "
                      "kJ/mol: per mole of solvent, mu = (mu/k_BT) R T, which needs "
                      "'Temperature'.");
    prm.declare_entry("Temperature",
                      "0",
                      Double(),
                      "The absolute temperature T in K, for a chemical potential per mole and "
                      "for 'Solvent molar volume'. 0: not given.");
    prm.declare_entry("Solvent molar volume",
                      "0",
                      Double(),
                      "The solvent's molar volume v_m in cm^3/mol (water: 18.07). With "
                      "'Temperature', the scene's k_BT/nu = G/(N nu) is checked against R T / "
                      "v_m (within 0.1 %): a laboratory scene's 'Material/N nu' must be G v_m "
                      "/(R T), which the error message gives. 0: not given.");
    prm.declare_entry("Length scale",
                      "0",
                      Double(),
                      "The laboratory length (in 'Length unit') of one normalised length. "
                      "laboratory: leave 0, it is 'Time stepping/Characteristic length' (filled "
                      "in by the conversion); normalised with unit names: give it, to have "
                      "statistics_units.csv.");
    prm.declare_entry("Time scale",
                      "0",
                      Double(),
                      "The laboratory value (in 'Time unit') of tau_d; laboratory: leave 0, it "
                      "is L^2/D.");
    prm.declare_entry("Stress scale",
                      "0",
                      Double(),
                      "The laboratory value (in 'Stress unit') of one normalised stress; "
                      "laboratory: leave 0, it is 'Material/Shear modulus'.");
    prm.leave_subsection();
  }


  Units
  Units::convert_scene(dealii::ParameterHandler &prm)
  {
    Units u;
    prm.enter_subsection("Units");
    u.laboratory  = prm.get("Scene values") == "laboratory";
    u.length_unit = dealii::Utilities::trim(prm.get("Length unit"));
    u.time_unit   = dealii::Utilities::trim(prm.get("Time unit"));
    u.stress_unit = dealii::Utilities::trim(prm.get("Stress unit"));
    u.force_unit  = dealii::Utilities::trim(prm.get("Force unit"));
    u.mu_unit     = dealii::Utilities::trim(prm.get("Chemical potential unit"));
    prm.leave_subsection();
    u.units = u.laboratory || !u.length_unit.empty() || !u.time_unit.empty() ||
              !u.stress_unit.empty() || !u.force_unit.empty();
    if (!u.units)
      return u;

    const double length_si = unit_in_si(length_units, u.length_unit, "Units/Length unit");
    unit_in_si(time_units, u.time_unit, "Units/Time unit");
    const double stress_si = unit_in_si(stress_units, u.stress_unit, "Units/Stress unit");
    if (!u.force_unit.empty())
      u.force_factor = stress_si * length_si * length_si /
                       unit_in_si(force_units, u.force_unit, "Units/Force unit");
    const double mu_per_mole = unit_in_si(mu_units, u.mu_unit, "Units/Chemical potential unit");

    prm.enter_subsection("Units");
    const double temperature   = prm.get_double("Temperature");
    const double molar_volume  = prm.get_double("Solvent molar volume");
    const double length_scale  = prm.get_double("Length scale");
    const double time_scale    = prm.get_double("Time scale");
    const double stress_scale  = prm.get_double("Stress scale");
    const bool   needs_solvent = mu_per_mole > 0.;
    require(temperature >= 0.,
            "Units/Temperature",
            "is " + shortest_text(temperature) + " K, below the absolute zero",
            "give the absolute temperature in K, e.g. 298.15");
    require(temperature > 0. || !needs_solvent,
            "Units/Temperature",
            "is not given (0), but the chemical potential unit '" + u.mu_unit +
              "' (per mole) needs it: mu = (mu/k_BT) R T",
            "give the absolute temperature in K, e.g. 298.15, or 'Chemical potential unit = kT'");
    require(
      temperature > 0. || molar_volume == 0.,
      "Units/Temperature",
      "is not given (0), but 'Solvent molar volume' needs it for R T / v_m",
      "give the absolute temperature in K, e.g. 298.15, or leave 'Solvent molar volume' at 0");
    require(molar_volume >= 0.,
            "Units/Solvent molar volume",
            "is " + shortest_text(molar_volume) + ", not a volume",
            "give the solvent's molar volume in cm^3/mol (water: 18.07), or 0");
    if (u.laboratory)
      for (const auto &[entry, value] : {std::make_pair("Length scale", length_scale),
                                         std::make_pair("Time scale", time_scale),
                                         std::make_pair("Stress scale", stress_scale)})
        require(value == 0.,
                std::string("Units/") + entry,
                "is " + shortest_text(value) +
                  " in a scene of laboratory values, whose scales are its own "
                  "'Characteristic length', L^2/D and 'Shear modulus'",
                "leave it at 0 (or write the scene in normalised values)");
    else
      {
        u.length = positive(prm,
                            "Length scale",
                            "a scene of normalised values with laboratory units needs the "
                            "laboratory length of one normalised length",
                            "give it in '" + u.length_unit + "', e.g. the characteristic length");
        u.time   = positive(prm,
                          "Time scale",
                          "a scene of normalised values with laboratory units needs the "
                            "laboratory value of tau_d",
                          "give tau_d = L^2/D in '" + u.time_unit + "'");
        u.stress = positive(prm,
                            "Stress scale",
                            "a scene of normalised values with laboratory units needs the "
                            "laboratory value of one normalised stress",
                            "give the shear modulus G in '" + u.stress_unit + "'");
      }
    prm.leave_subsection();

    // The scales: in a laboratory scene its own L, D and G.
    const double L =
      prm.get_double(std::vector<std::string>{"Time stepping"}, "Characteristic length");
    const double D    = prm.get_double(std::vector<std::string>{"Material"}, "Diffusivity");
    const double G    = prm.get_double(std::vector<std::string>{"Material"}, "Shear modulus");
    const double N_nu = prm.get_double(std::vector<std::string>{"Material"}, "N nu");
    if (u.laboratory)
      {
        for (const auto &[entry, value, what] :
             {std::make_tuple("Time stepping/Characteristic length", L, "is the length scale"),
              std::make_tuple("Material/Diffusivity",
                              D,
                              "sets, with L, the time scale tau_d = L^2/D"),
              std::make_tuple("Material/Shear modulus", G, "is the stress scale")})
          require(value > 0.,
                  entry,
                  "is " + shortest_text(value) + ", but in a scene of laboratory values it " + what,
                  "give a positive value in the laboratory units ('Units')");
        u.length = L;
        u.time   = L * L / D;
        u.stress = G;
      }
    u.mu = needs_solvent ? gas_constant * temperature / mu_per_mole : 1.;
    // The unit of statistics.csv's 'time' is tau_d D/L^2 (normalised L and D).
    u.scene_time = u.laboratory ? u.time : u.time * D / (L * L);

    const std::string dimension_text = prm.get("Dimension");
    const bool        plane_strain =
      dimension_text == "2" &&
      prm.get(std::vector<std::string>{"Background grid"}, "Coordinate system") != "axisymmetric";
    u.measure_dim = plane_strain ? 2 : 3;
    u.pieces      = dealii::Utilities::split_string_list(
      prm.get(std::vector<std::string>{"Boundary conditions"}, "Pieces"));
    u.obstacles = dealii::Utilities::split_string_list(
      prm.get(std::vector<std::string>{"Contact"}, "Obstacles"));

    // k_BT/nu of the scene against the solvent's R T / v_m.
    const double       kT_over_nu = (u.laboratory ? G : u.stress * G) / N_nu; // in the stress unit
    std::ostringstream solvent;
    solvent << "k_BT/nu = G/(N nu) = " << shown(kT_over_nu) << ' ' << u.stress_unit;
    if (molar_volume > 0.)
      {
        const double expected = gas_constant * temperature / (molar_volume * 1e-6) / stress_si;
        const double fitting  = N_nu * kT_over_nu / expected;
        solvent << " (R T / v_m = " << shown(expected) << ' ' << u.stress_unit << ')';
        require(std::abs(kT_over_nu / expected - 1.) <= 1e-3,
                "Material/N nu",
                "is " + shortest_text(N_nu) + ", so that k_BT/nu = G/(N nu) = " +
                  shown(kT_over_nu) + " " + u.stress_unit + ", but the solvent ('Units/" +
                  "Temperature' and 'Solvent molar volume') gives R T / v_m = " + shown(expected) +
                  " " + u.stress_unit,
                "set 'Material/N nu' to G v_m/(R T) = " + shown(fitting) +
                  ", or correct the temperature or the molar volume");
      }

    std::ostringstream scales;
    scales << "lengths in " << u.length_unit << " (scale " << shortest_text(u.length) << ' '
           << u.length_unit << "), times in " << u.time_unit
           << " (tau_d = " << shortest_text(u.time) << ' ' << u.time_unit << "), stresses in "
           << u.stress_unit << " (scale " << shortest_text(u.stress) << ' ' << u.stress_unit
           << "), chemical potentials in " << u.mu_unit;
    if (needs_solvent)
      scales << " (k_BT = " << shown(u.mu) << ' ' << u.mu_unit << ')';
    u.scale_notes = {scales.str(), solvent.str()};
    if (!u.laboratory)
      return u;

    // Convert every entry of known dimension.
    const unsigned int dim           = dimension_text == "3" ? 3 : 2;
    const auto         to_normalised = [&u](const double x, const Quantity q) {
      switch (q)
        {
          case Quantity::length:
            return x / u.length;
          case Quantity::time:
            return x / u.time;
          case Quantity::rate:
            return x * u.time;
          case Quantity::stress:
            return x / u.stress;
          case Quantity::chemical_potential:
            return x / u.mu;
          case Quantity::diffusivity:
            return x / (u.length * u.length / u.time);
          case Quantity::velocity:
            return x / (u.length / u.time);
          default:
            return x;
        }
    };
    const auto value_scale = [&u](const Quantity q) {
      switch (q)
        {
          case Quantity::length:
            return u.length;
          case Quantity::stress:
            return u.stress;
          case Quantity::chemical_potential:
            return u.mu;
          case Quantity::velocity:
            return u.length / u.time;
          default:
            return 1.;
        }
    };
    const std::map<Quantity, std::string> unit_names = {
      {Quantity::length, u.length_unit},
      {Quantity::time, u.time_unit},
      {Quantity::rate, "1/" + u.time_unit},
      {Quantity::stress, u.stress_unit},
      {Quantity::chemical_potential, u.mu_unit},
      {Quantity::diffusivity, u.length_unit + "^2/" + u.time_unit},
      {Quantity::velocity, u.length_unit + "/" + u.time_unit}};
    // An expression in lab positions (and time): the normalised ones scaled back.
    const auto wrap_variables = [&](const std::string              &expression,
                                    const std::vector<std::string> &lengths,
                                    const std::string              &time_name) {
      std::map<std::string, std::string> replacements;
      if (u.length != 1.)
        for (const auto &name : lengths)
          replacements[name] = "(" + name + "*" + shortest_text(u.length) + ")";
      if (!time_name.empty() && u.time != 1.)
        replacements[time_name] = "(" + time_name + "*" + shortest_text(u.time) + ")";
      return substitute(expression, replacements);
    };
    const std::vector<std::string> xyz =
      dim == 3 ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"};

    for (const auto &entry : all_entries(prm))
      {
        const EntryRule *rule = rule_of(entry.path);
        if (rule == nullptr)
          {
            require(entry.value == entry.default_value,
                    entry.path,
                    "is '" + entry.value +
                      "', and its physical dimension is not known to the conversion of a "
                      "scene of laboratory values ('Units/Scene values = laboratory')",
                    "leave it at its default '" + entry.default_value +
                      "', or write the scene in normalised values");
            continue;
          }
        if (rule->quantity == Quantity::refused)
          {
            require(dealii::Utilities::trim(entry.value).empty(),
                    entry.path,
                    "is '" + entry.value +
                      "', whose coordinates cannot be converted from laboratory units "
                      "('Units/Scene values = laboratory')",
                    "write the scene in normalised values, the mesh scaled by the "
                    "characteristic length");
            continue;
          }
        std::string converted = entry.value;
        switch (rule->form)
          {
            case Form::numbers:
              if (rule->quantity != Quantity::none && rule->quantity != Quantity::constants)
                converted = map_numbers(entry.value, [&](const double x) {
                  return to_normalised(x, rule->quantity);
                });
              break;
            case Form::holes:
              {
                converted.clear();
                for (const auto &hole : dealii::Utilities::split_string_list(entry.value, ';'))
                  {
                    const auto  parts = dealii::Utilities::split_string_list(hole, ':');
                    std::string text;
                    for (std::size_t k = 0; k < parts.size(); ++k)
                      text += (k ? " : " : "") +
                              (k < 2 ? map_numbers(parts[k],
                                                   [&](const double x) {
                                                     return to_normalised(x, Quantity::length);
                                                   })
                                     : parts[k]);
                    converted += (converted.empty() ? "" : "; ") + text;
                  }
                break;
              }
            case Form::selector:
              if (dealii::Utilities::trim(entry.value).rfind("boundary id", 0) != 0)
                converted = wrap_variables(entry.value, xyz, "");
              break;
            case Form::level_set:
              converted = wrap_variables(entry.value, xyz, "");
              break;
            case Form::moving_level_set:
              converted = wrap_variables(entry.value, xyz, "t");
              break;
            case Form::function:
              {
                const std::string section = entry.path.substr(0, entry.path.rfind('/'));
                const auto        names =
                  dealii::Utilities::split_string_list(get_entry(prm, section + "/Variable names"));
                std::vector<std::string> lengths;
                std::string              time_name;
                for (std::size_t k = 0; k < names.size(); ++k)
                  if (k < dim)
                    lengths.push_back(names[k]);
                  else
                    time_name = names[k];
                const double scale = value_scale(rule->quantity);
                converted.clear();
                for (const auto &component : dealii::Utilities::split_string_list(entry.value, ';'))
                  {
                    double      x;
                    std::string text;
                    if (read_number(component, x))
                      text = to_normalised(x, rule->quantity) == x
                               ? component
                               : shortest_text(to_normalised(x, rule->quantity));
                    else
                      {
                        text = wrap_variables(component, lengths, time_name);
                        if (scale != 1.)
                          text = "(" + text + ")/" + shortest_text(scale);
                      }
                    converted += (converted.empty() ? "" : "; ") + text;
                  }
                break;
              }
          }
        if (converted == entry.value)
          continue;
        set_entry(prm, entry.path, converted);
        u.conversions.push_back({entry.path,
                                 entry.value,
                                 converted,
                                 rule->form == Form::function       ? ""
                                 : unit_names.count(rule->quantity) ? unit_names.at(rule->quantity)
                                                                    : ""});
      }
    // parameters.prm: a normalised scene that reads its outputs in the same units.
    set_entry(prm, "Units/Scene values", "normalised");
    set_entry(prm, "Units/Length scale", shortest_text(u.length));
    set_entry(prm, "Units/Time scale", shortest_text(u.time));
    set_entry(prm, "Units/Stress scale", shortest_text(u.stress));
    return u;
  }


  bool
  Units::enabled() const
  {
    return units;
  }


  bool
  Units::converted() const
  {
    return laboratory;
  }


  void
  Units::print_conversions(std::ostream &out) const
  {
    if (!units)
      return;
    out << "  units: " << scale_notes[0] << "; " << scale_notes[1] << '\n';
    if (!laboratory)
      {
        out << "    (normalised scene values; statistics_units.csv in these units)\n";
        return;
      }
    out << "  the scene's laboratory values converted to the normalised values the run uses "
           "('Units/Scene values = laboratory'):\n";
    for (const auto &c : conversions)
      out << "    " << c.entry << ": " << c.laboratory << (c.unit.empty() ? "" : " " + c.unit)
          << " -> " << c.normalised << '\n';
  }


  std::pair<std::string, double>
  Units::column_unit(const std::string &column) const
  {
    const std::string L   = length_unit;
    const bool        pe  = measure_dim == 2; // per unit thickness
    const double      NaN = std::numeric_limits<double>::quiet_NaN();
    switch (column_kind(column, pieces, obstacles))
      {
        case Column::dimensionless:
          return {"1", 1.};
        case Column::degrees:
          return {"deg", 1.};
        case Column::tau_d:
          return {"tau_d", 1.};
        case Column::step:
          return {time_unit, time};
        case Column::scene_time:
          return {time_unit, scene_time};
        case Column::length:
          return {L, length};
        case Column::inverse_length:
          return {"1/" + L, 1. / length};
        case Column::chemical_potential:
          return {mu_unit, mu};
        case Column::force:
          {
            const double in_stress_units = stress * length * (pe ? 1. : length);
            if (force_factor == 0.)
              return {stress_unit + "*" + L + (pe ? "" : "^2"), in_stress_units};
            return {force_unit + (pe ? "/" + L : ""), in_stress_units * force_factor};
          }
        case Column::area:
          return {L + "^2" + (pe ? "/" + L : ""), length * (pe ? 1. : length)};
        case Column::volume:
          return {L + "^3" + (pe ? "/" + L : ""), length * length * (pe ? 1. : length)};
        case Column::volume_rate:
          return {L + "^3/" + time_unit + (pe ? "/" + L : ""),
                  length * length * (pe ? 1. : length) / scene_time};
        case Column::wall:
          return {"s, wall clock", 1.};
        default:
          return {"normalised", NaN};
      }
  }


  void
  Units::write_statistics(const std::string &directory) const
  {
    const std::string source = directory + "/statistics.csv";
    std::ifstream     in(source);
    if (!units || !in)
      return;
    const std::string   path = directory + "/statistics_units.csv";
    std::ofstream       out(path + ".tmp");
    std::string         line;
    std::vector<double> factors;
    if (std::getline(in, line))
      {
        std::string header;
        for (const auto &column : csv_fields(line))
          {
            const auto [unit, factor] = column_unit(column);
            header += (header.empty() ? "" : ",") + column + " [" + unit + "]";
            factors.push_back(factor);
          }
        out << header << '\n';
      }
    while (std::getline(in, line))
      {
        const auto  fields = csv_fields(line);
        std::string row;
        for (std::size_t k = 0; k < fields.size(); ++k)
          {
            double      x;
            std::string field = fields[k];
            if (k < factors.size() && !std::isnan(factors[k]) && read_number(field, x))
              {
                std::ostringstream text;
                text << std::setprecision(10) << x * factors[k];
                field = text.str();
              }
            row += (k ? "," : "") + field;
          }
        out << row << '\n';
      }
    out.close();
    if (!out)
      throw std::runtime_error("cannot write '" + path + ".tmp' (disk full?)");
    std::filesystem::rename(path + ".tmp", path);
  }


  std::string
  Units::annotate_reference(const std::string &listing)
  {
    std::istringstream       in(listing);
    std::ostringstream       out;
    std::vector<std::string> sections;
    for (std::string line; std::getline(in, line);)
      {
        const auto        first   = line.find_first_not_of(' ');
        const std::string trimmed = first == std::string::npos ? "" : line.substr(first);
        if (trimmed.rfind("subsection ", 0) == 0)
          sections.push_back(dealii::Utilities::trim(trimmed.substr(11)));
        else if (trimmed == "end" && !sections.empty())
          sections.pop_back();
        else if (trimmed.rfind("set ", 0) == 0)
          {
            std::string path;
            for (const auto &section : sections)
              path += section + "/";
            path += dealii::Utilities::trim(trimmed.substr(4, trimmed.find('=') - 4));
            out << line.substr(0, first)
                << "# Laboratory units: " << rule_description(rule_of(path)) << '\n';
          }
        out << line << '\n';
      }
    return out.str();
  }
} // namespace GelMPM
