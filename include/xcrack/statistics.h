#ifndef xcrack_statistics_h
#define xcrack_statistics_h

#include <map>
#include <string>
#include <vector>

namespace xcrack
{
  /**
   * The run's table of one row per solve, written as `statistics.csv`.
   * Columns keep the order in which they first appear; a row that lacks a
   * column leaves its cell empty. Column names are fixed by DESIGN.md
   * ("Outputs that others read") so that scripts can rely on them.
   */
  class Statistics
  {
  public:
    /// Start a new row; later add_value() calls fill it.
    void
    start_row();

    void
    add_value(const std::string &column, const double value);

    void
    add_value(const std::string &column, const unsigned long long value);

    /// A word or a few (no comma, no newline): a flag's reason.
    void
    add_text(const std::string &column, const std::string &text);

    /// Value of @p column in row @p row (NaN if the cell is empty).
    double
    get(const std::string &column, const unsigned int row) const;

    /// The text of @p column in row @p row (empty if it holds none).
    std::string
    text(const std::string &column, const unsigned int row) const;

    unsigned int
    n_rows() const;

    /// Write a header line and all rows, comma separated.
    void
    write_csv(const std::string &filename) const;

    /// Write or read with a boost archive (checkpoints).
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &columns &rows;
    }

  private:
    struct Cell
    {
      double      value      = 0;
      bool        is_integer = false;
      std::string text;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &value &is_integer &text;
      }
    };
    std::vector<std::string>                 columns;
    std::vector<std::map<std::string, Cell>> rows;
  };
} // namespace xcrack

#endif
