#pragma once
// Shared support of the lecture demos (gnuplot-iostream).
//
// Every demo accepts `--out DIR` or `--csv DIR`. With --out, or without a DISPLAY, it writes
// PNG (pngcairo) and CSV files into DIR (default ./demo_output). With --csv it writes the CSV
// files into DIR and still opens windows when there is a DISPLAY. With a DISPLAY and neither
// option it opens
// gnuplot windows (needs a gnuplot with a window terminal, e.g. Debian's gnuplot-qt; a
// gnuplot without one falls back to files, and so does a machine without gnuplot, which
// then gets the CSV files only).
//
// A demo may declare its parameters in one table (Parameter: name, default, unit, help, and the
// allowed words of a choice), which run() parses as `--name VALUE` (or `--name=VALUE`) and lists
// with their defaults under `--help`. The body reads them with Options::number(), integer() and
// text(). An unknown argument or a value that does not parse is a one-line message and exit 2.

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gnuplot-iostream.h>

namespace fmbd::demo {

/// One parameter a lecturer may change on the command line: `--<name> VALUE`.
struct Parameter {
  std::string name;                  ///< without the dashes, e.g. "spin-rate"
  std::string value;                 ///< the default, as it would be typed
  std::string unit;                  ///< e.g. "rad/s", "-" for a pure number; empty: a count or a word
  std::string help;                  ///< one line
  std::vector<std::string> choices;  ///< the allowed words (a choice); empty: a number

  Parameter(std::string name_, std::string value_, std::string unit_, std::string help_,
            std::vector<std::string> choices_ = {})
      : name(std::move(name_)), value(std::move(value_)), unit(std::move(unit_)), help(std::move(help_)),
        choices(std::move(choices_)) {}
};

struct Options {
  std::string name;     ///< demo name, used for file names
  bool window = false;  ///< gnuplot window instead of files
  bool gnuplot = true;  ///< gnuplot available at all
  std::string out_dir;  ///< where PNG and CSV files go (file mode)
  std::vector<Parameter> parameters;  ///< the demo's table, with the values given on the command line

  /// The value of a numeric parameter. Throws std::logic_error for a name not in the table.
  double number(const std::string& parameter) const;
  /// The value of a numeric parameter that must be a whole number.
  int integer(const std::string& parameter) const;
  /// The value of a parameter as typed (the word of a choice).
  const std::string& text(const std::string& parameter) const;
};

/// A table of numbers with named columns, written as CSV and sent to gnuplot.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  void add(std::vector<double> row) { rows.push_back(std::move(row)); }
};

/// What a figure file holds: one picture, or an animation whose frames are successive plots.
enum class Format { png, gif_animation };

/// One gnuplot figure: a window, or `<out_dir>/<file>.png` (`.gif` for an animation). Write
/// gnuplot commands to gp(); inline data blocks with send(); end each animation frame with
/// end_frame(). The figure is finished when the object is destroyed.
class Figure {
 public:
  Figure(const Options& options, const std::string& file, int width = 1000, int height = 650,
         Format format = Format::png);
  ~Figure();
  Figure(const Figure&) = delete;
  Figure& operator=(const Figure&) = delete;

  Gnuplot& gp();
  /// Sends columns `cols` (indices into table.columns) of `table` as an inline data block.
  void send(const Table& table, const std::vector<int>& cols);
  /// Ends an animation frame: in a window it pauses so that the motion can be seen.
  void end_frame(double seconds);
  bool active() const { return gp_ != nullptr; }

 private:
  std::unique_ptr<Gnuplot> gp_;
  bool window_ = false;
};

/// Writes `<out_dir>/<file>.csv` (in window mode too, if --csv was given). Every column name
/// carries its unit in brackets ("t [s]"); throws std::invalid_argument naming the column if
/// one does not. A non-finite value (a missing one) is written as an empty field.
void write_csv(const Options& options, const std::string& file, const Table& table);

/// Parses the command line, runs `body`, and turns any exception into a one-line message
/// and exit status 1 (for example "not implemented yet: M01T1 rotation" on the skeleton).
/// `--help` prints the usage with every parameter of `parameters` and its default, and exits 0;
/// an unknown argument, a missing value, a number that does not parse (or is not whole for a count,
/// a parameter without unit or choices) or a word outside a choice prints what is wrong and exits 2.
int run(int argc, char** argv, const std::string& name, const std::vector<Parameter>& parameters,
        const std::function<void(const Options&)>& body);
/// The same for a demo without parameters.
int run(int argc, char** argv, const std::string& name, const std::function<void(const Options&)>& body);

}  // namespace fmbd::demo
