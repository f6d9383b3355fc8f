#ifndef gelmpm_core_unit_tables_h
#define gelmpm_core_unit_tables_h

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * The physical dimension of every scene entry and statistics.csv column: the tables of the
   * laboratory-units conversion (Units), kept apart from its logic.
   */
  namespace UnitTables
  {
    /** The physical dimension of a scene entry. */
    enum class Quantity
    {
      none,      // no physical dimension, or not a number: not converted
      constants, // constants of an expression: in laboratory units, as the expression is
      length,    //
      time,      //
      rate,      // per unit time
      stress,    //
      chemical_potential,
      diffusivity, // length^2 / time
      velocity,    // length / time: a solvent volume flux per area
      refused      // cannot be converted: an input error in a laboratory scene
    };

    /** How the entry's text holds its numbers. */
    enum class Form
    {
      numbers,         // numbers, lists of them, 'a : b' pairs; words (e.g. 'onset') are kept
      holes,           // 'centre : radius [: axis direction]; ...': the axis is not converted
      function,        // a deal.II function expression in 'Variable names' beside it
      selector,        // an expression in x, y (, z) and normals (not converted), true or false
      level_set,       // an expression in x, y (, z), only its sign matters
      moving_level_set // a level_set in x, y (, z) and the time t
    };

    struct EntryRule
    {
      const char *path; // '*' stands for one name (a piece, a region, an obstacle)
      Quantity    quantity;
      Form        form = Form::numbers;
    };

    /**
     * Every entry of a scene with its physical dimension: the one table of the conversion.
     * An entry that is not here is refused in a laboratory scene unless it is at its default
     * (tests/units checks that every declared entry is here).
     */
    const std::vector<EntryRule> &
    entry_rules();


    /** Columns of statistics.csv, by their physical dimension. */
    enum class Column
    {
      dimensionless,
      degrees,
      tau_d,      // t_over_tau_d: stays in tau_d
      step,       // dt, in tau_d
      scene_time, // time, in the unit of the scene's time
      length,
      inverse_length,
      chemical_potential,
      force,
      area,
      volume,
      volume_rate,
      wall,
      unknown
    };

    /**
     * The physical dimension of column @p column of statistics.csv, whose pieces and obstacles
     * are named @p pieces and @p obstacles; Column::unknown if the table does not know it.
     */
    Column
    column_kind(const std::string              &column,
                const std::vector<std::string> &pieces,
                const std::vector<std::string> &obstacles);
  } // namespace UnitTables
} // namespace GelMPM

#endif
