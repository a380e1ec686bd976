#include <deal.II/base/exceptions.h>

#include <xcrack/input_error.h>
#include <xcrack/output_file.h>
#include <xcrack/statistics.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace xcrack
{
  void
  Statistics::start_row()
  {
    rows.emplace_back();
  }



  void
  Statistics::add_value(const std::string &column, const double value)
  {
    // The last guard before a number reaches a file that others trust.
    if (!std::isfinite(value))
      throw NumericalError(column + " is not finite (" + std::to_string(value) +
                           "); the run stops rather than write it.");
    if (rows.empty())
      start_row();
    if (std::find(columns.begin(), columns.end(), column) == columns.end())
      columns.push_back(column);
    rows.back()[column] = {value, false, {}};
  }



  void
  Statistics::add_value(const std::string       &column,
                        const unsigned long long value)
  {
    add_value(column, static_cast<double>(value));
    rows.back()[column].is_integer = true;
  }



  void
  Statistics::add_text(const std::string &column, const std::string &text)
  {
    Assert(text.find_first_of(",\n\"") == std::string::npos,
           dealii::ExcMessage("A CSV cell cannot hold '" + text + "'."));
    // (An empty text leaves the cell empty.)
    if (text.empty())
      return;
    add_value(column, 0.);
    rows.back()[column].text = text;
  }



  double
  Statistics::get(const std::string &column, const unsigned int row) const
  {
    if (row >= rows.size())
      throw std::out_of_range("Statistics: no row " + std::to_string(row));
    const auto it = rows[row].find(column);
    return (it == rows[row].end() ? std::numeric_limits<double>::quiet_NaN() :
                                    it->second.value);
  }



  std::string
  Statistics::text(const std::string &column, const unsigned int row) const
  {
    if (row >= rows.size())
      throw std::out_of_range("Statistics: no row " + std::to_string(row));
    const auto it = rows[row].find(column);
    return (it == rows[row].end() ? std::string() : it->second.text);
  }



  unsigned int
  Statistics::n_rows() const
  {
    return rows.size();
  }



  void
  Statistics::write_csv(const std::string &filename) const
  {
    write_file(filename, [this](std::ostream &out) {
      for (unsigned int c = 0; c < columns.size(); ++c)
        out << (c == 0 ? "" : ",") << columns[c];
      out << '\n';
      for (const auto &row : rows)
        {
          for (unsigned int c = 0; c < columns.size(); ++c)
            {
              if (c > 0)
                out << ',';
              const auto it = row.find(columns[c]);
              if (it == row.end())
                continue;
              if (!it->second.text.empty())
                out << it->second.text;
              else if (it->second.is_integer)
                out << static_cast<long long>(it->second.value);
              else
                out << std::setprecision(10) << it->second.value;
            }
          out << '\n';
        }
    });
  }
} // namespace xcrack
