// Matrix Market files and node tables of external FE models (given code, module 5).
#include "fmbd/matrix_market.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <locale>
#include <sstream>
#include <string_view>
#include <utility>

namespace fmbd {

namespace {

constexpr double kSymmetryTolerance = 1e-10;  // |a_ij - a_ji| <= tol * max |a|
constexpr long long kMaxDimension = 100000000;  // rows and cols of a matrix that is read

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FeFileError(path, 0, "cannot open the file for reading");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw FeFileError(path, 0, "read error");
  return s.str();
}

// Splits a text into lines (without '\n' or a trailing '\r'), one at a time.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++number_;
    return true;
  }
  int number() const { return number_; }  // of the line last returned, from 1

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Whitespace-separated fields of a line (at most `max` + 1, so that "too many" is seen).
std::vector<std::string_view> fields(std::string_view line, std::size_t max) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size() && out.size() <= max) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool is_blank(std::string_view line) {
  return std::all_of(line.begin(), line.end(), [](char c) { return is_space(c); });
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// from_chars does not take a leading '+'.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
  return token;
}

bool parse_integer(std::string_view token, long long& value) {
  token = without_plus(token);
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

bool parse_double(std::string_view token, double& value) {
  token = without_plus(token);
#if defined(__cpp_lib_to_chars)
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
#else  // libc++ before 17 (clang on macOS) has no floating-point from_chars: a stream, locale-free
  std::istringstream in{std::string(token)};
  in.imbue(std::locale::classic());
  in >> value;
  return !token.empty() && !in.fail() && in.peek() == std::char_traits<char>::eof();
#endif
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

// A double as the shortest text that reads back exactly.
void append_number(std::string& out, double value) {
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

void append_number(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

// Writes `text` to a new file at `path`.
void write_whole_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw FeFileError(path, 0, "cannot open the file for writing");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  if (!out) throw FeFileError(path, 0, "write error");
}

double max_abs(const SparseMat& A) {
  double m = 0.0;
  for (int c = 0; c < A.outerSize(); ++c)
    for (SparseMat::InnerIterator it(A, c); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

// A read matrix and the line of its size declaration (for later messages).
struct MarketFile {
  SparseMat A;
  int size_line = 0;
};

// The header "%%MatrixMarket matrix coordinate real|integer symmetric|general" on the first line:
// whether the file says symmetric (it then holds the lower triangle).
bool read_header(const std::string& path, LineReader& reader) {
  std::string_view line;
  if (!reader.next(line)) throw FeFileError(path, 1, "the file is empty; expected a %%MatrixMarket header");
  const std::vector<std::string_view> head = fields(line, 5);
  if (head.size() != 5 || lower(head[0]) != "%%matrixmarket")
    throw FeFileError(path, 1, "expected the header '%%MatrixMarket matrix coordinate real symmetric|general', got " +
                                   quoted(line));
  if (lower(head[1]) != "matrix") throw FeFileError(path, 1, "the object must be 'matrix', got " + quoted(head[1]));
  if (lower(head[2]) != "coordinate")
    throw FeFileError(path, 1, "only the sparse 'coordinate' format is read, got " + quoted(head[2]));
  const std::string field = lower(head[3]);
  if (field != "real" && field != "integer")
    throw FeFileError(path, 1, "the field must be 'real' or 'integer', got " + quoted(head[3]));
  const std::string symmetry = lower(head[4]);
  if (symmetry != "symmetric" && symmetry != "general")
    throw FeFileError(path, 1, "the symmetry must be 'symmetric' or 'general', got " + quoted(head[4]));
  return symmetry == "symmetric";
}

// The size line "rows cols entries" and its line number.
struct MarketSize {
  long long rows = 0, cols = 0, count = 0;
  int line = 0;
};

// Reads the size line: the first line after the header that is neither a comment nor blank. A
// matrix that is symmetric (by the file or by `shape`) must be square.
MarketSize read_size(const std::string& path, LineReader& reader, bool symmetric_file, MatrixShape shape) {
  std::string_view line;
  bool found = false;
  while (reader.next(line)) {
    if (is_blank(line) || line.front() == '%') continue;
    found = true;
    break;
  }
  if (!found) throw FeFileError(path, reader.number() + 1, "the file ends before the size line 'rows cols entries'");
  MarketSize size;
  size.line = reader.number();
  const std::vector<std::string_view> f = fields(line, 3);
  if (f.size() != 3 || !parse_integer(f[0], size.rows) || !parse_integer(f[1], size.cols) ||
      !parse_integer(f[2], size.count))
    throw FeFileError(path, size.line,
                      "expected the size line 'rows cols entries' (three integers), got " + quoted(line));
  const long long rows = size.rows, cols = size.cols, count = size.count;
  if (rows < 1 || cols < 1 || count < 0 || rows > kMaxDimension || cols > kMaxDimension)
    throw FeFileError(path, size.line, "the size line declares " + std::to_string(rows) + " x " +
                                           std::to_string(cols) + " with " + std::to_string(count) +
                                           " entries; rows and cols must lie in 1 .. 10^8, entries not be negative");
  if ((symmetric_file || shape == MatrixShape::symmetric) && rows != cols)
    throw FeFileError(path, size.line, "the matrix is " + std::to_string(rows) + " x " + std::to_string(cols) +
                                           " but must be square" +
                                           (symmetric_file ? " (the file says symmetric)" : ""));
  return size;
}

// The entries as triplets, and the file line of each entry in file order (a symmetric file's
// off-diagonal entries add their mirror too).
struct MarketEntries {
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<int> lines;
};

// Reads the entries after the size line: exactly the declared count, each "row col value" with
// 1-based indices inside the size (on or below the diagonal in a symmetric file).
MarketEntries read_entries(const std::string& path, LineReader& reader, const MarketSize& size, bool symmetric_file,
                           std::size_t text_size) {
  const long long rows = size.rows, cols = size.cols, count = size.count;
  MarketEntries out;
  // No more entries than lines of at least six bytes ("1 1 1\n"), whatever the size line says.
  const auto expected = static_cast<std::size_t>(std::min<long long>(count, static_cast<long long>(text_size / 6 + 1)));
  out.triplets.reserve(expected * (symmetric_file ? 2 : 1));
  out.lines.reserve(expected);
  std::string_view line;
  long long read = 0;
  while (reader.next(line)) {
    if (is_blank(line) || line.front() == '%') continue;
    const int at = reader.number();
    if (read == count)
      throw FeFileError(path, at, "more entries than the " + std::to_string(count) + " declared on line " +
                                      std::to_string(size.line));
    const std::vector<std::string_view> entry = fields(line, 3);
    if (entry.size() != 3)
      throw FeFileError(path, at, "expected an entry 'row col value' (three fields), got " + quoted(line));
    long long i = 0, j = 0;
    double value = 0.0;
    if (!parse_integer(entry[0], i))
      throw FeFileError(path, at, "the row index " + quoted(entry[0]) + " is not an integer");
    if (!parse_integer(entry[1], j))
      throw FeFileError(path, at, "the column index " + quoted(entry[1]) + " is not an integer");
    if (!parse_double(entry[2], value))
      throw FeFileError(path, at, "the value " + quoted(entry[2]) + " is not a number");
    if (!std::isfinite(value)) throw FeFileError(path, at, "the value " + quoted(entry[2]) + " is not finite");
    if (i < 1 || i > rows)
      throw FeFileError(path, at, "row index " + std::to_string(i) + " is outside 1 .. " + std::to_string(rows));
    if (j < 1 || j > cols)
      throw FeFileError(path, at, "column index " + std::to_string(j) + " is outside 1 .. " + std::to_string(cols));
    if (symmetric_file && i < j)
      throw FeFileError(path, at, "entry (" + std::to_string(i) + ", " + std::to_string(j) +
                                      ") lies above the diagonal; a symmetric file holds the lower triangle "
                                      "(row >= col)");
    const int r = static_cast<int>(i - 1), c = static_cast<int>(j - 1);
    out.triplets.emplace_back(r, c, value);
    if (symmetric_file && r != c) out.triplets.emplace_back(c, r, value);
    out.lines.push_back(at);
    ++read;
  }
  if (read < count)
    throw FeFileError(path, size.line, "the size line declares " + std::to_string(count) +
                                           " entries, but the file holds only " + std::to_string(read));
  return out;
}

// A general file read as a symmetric matrix: names the first entry in file order whose mirror
// differs (beyond the tolerance), or else makes A exactly symmetric, (A + A^T) / 2.
void require_symmetric(const std::string& path, SparseMat& A, const MarketEntries& entries) {
  const SparseMat At = A.transpose();
  const double bound = kSymmetryTolerance * max_abs(A);
  if (max_abs(SparseMat(A - At)) > bound) {
    for (std::size_t e = 0; e < entries.triplets.size(); ++e) {
      const int r = entries.triplets[e].row(), c = entries.triplets[e].col();
      const double a = A.coeff(r, c), b = A.coeff(c, r);
      if (std::abs(a - b) > bound) {
        std::ostringstream s;
        s.precision(17);
        s << "the matrix must be symmetric, but entry (" << r + 1 << ", " << c + 1 << ") = " << a << " and ("
          << c + 1 << ", " << r + 1 << ") = " << b;
        if (b == 0.0) s << " (no entry)";
        throw FeFileError(path, entries.lines[e], s.str());
      }
    }
  }
  A = SparseMat(0.5 * (A + At));
  A.makeCompressed();
}

MarketFile read_market(const std::string& path, MatrixShape shape) {
  const std::string text = read_whole_file(path);
  LineReader reader(text);
  const bool symmetric_file = read_header(path, reader);
  const MarketSize size = read_size(path, reader, symmetric_file, shape);
  const MarketEntries entries = read_entries(path, reader, size, symmetric_file, text.size());

  MarketFile out;
  out.size_line = size.line;
  out.A.resize(static_cast<Eigen::Index>(size.rows), static_cast<Eigen::Index>(size.cols));
  out.A.setFromTriplets(entries.triplets.begin(), entries.triplets.end());
  out.A.makeCompressed();
  if (shape == MatrixShape::symmetric && !symmetric_file) require_symmetric(path, out.A, entries);
  return out;
}

const char* dof_name(int d) {
  static const char* names[3] = {"u_x", "u_y", "psi"};
  return names[d];
}

}  // namespace

FeFileError::FeFileError(const std::string& path, int line, const std::string& message)
    : std::runtime_error(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + message),
      path_(path),
      line_(line) {}

SparseMat read_matrix_market(const std::string& path, MatrixShape shape) { return read_market(path, shape).A; }

void write_matrix_market(const std::string& path, const SparseMat& A) {
  if (A.rows() != A.cols())
    throw std::invalid_argument("write_matrix_market: the matrix is " + std::to_string(A.rows()) + " x " +
                                std::to_string(A.cols()) + ", not square");
  const double scale = max_abs(A);
  if (!std::isfinite(scale)) throw std::invalid_argument("write_matrix_market: the matrix is not finite");
  const SparseMat At = A.transpose();
  if (max_abs(SparseMat(A - At)) > kSymmetryTolerance * scale)
    throw std::invalid_argument("write_matrix_market: the matrix is not symmetric; only symmetric matrices are "
                                "written (lower triangle)");

  long long count = 0;
  for (int c = 0; c < A.outerSize(); ++c)
    for (SparseMat::InnerIterator it(A, c); it; ++it)
      if (it.row() >= it.col()) ++count;

  std::string text = "%%MatrixMarket matrix coordinate real symmetric\n% lower triangle (row >= col), 1-based\n";
  text.reserve(text.size() + static_cast<std::size_t>(count) * 36 + 64);
  append_number(text, static_cast<long long>(A.rows()));
  text += ' ';
  append_number(text, static_cast<long long>(A.cols()));
  text += ' ';
  append_number(text, count);
  text += '\n';
  for (int c = 0; c < A.outerSize(); ++c)
    for (SparseMat::InnerIterator it(A, c); it; ++it) {
      if (it.row() < it.col()) continue;
      append_number(text, static_cast<long long>(it.row()) + 1);
      text += ' ';
      append_number(text, static_cast<long long>(it.col()) + 1);
      text += ' ';
      append_number(text, it.value());
      text += '\n';
    }
  write_whole_file(path, text);
}

NodeTable read_node_table(const std::string& path, int num_dofs) {
  const std::string text = read_whole_file(path);
  LineReader reader(text);
  std::string_view line;
  NodeTable table;
  std::vector<int> owner_line(static_cast<std::size_t>(std::max(num_dofs, 0)), 0);  // 0: DOF not used yet
  std::vector<std::pair<int, int>> owner(owner_line.size());                         // (node, dof within node)
  while (reader.next(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    if (is_blank(line)) continue;
    const int at = reader.number();
    const int node = table.num_nodes();
    const std::vector<std::string_view> f = fields(line, 5);
    if (f.size() != 5)
      throw FeFileError(path, at, "node " + std::to_string(node) + ": expected 'x y dof_ux dof_uy dof_psi' (five "
                                  "fields), got " + quoted(line));
    Vec2 x;
    for (int k = 0; k < 2; ++k) {
      if (!parse_double(f[k], x(k)))
        throw FeFileError(path, at, "node " + std::to_string(node) + ": the coordinate " + quoted(f[k]) +
                                        " is not a number");
      if (!std::isfinite(x(k)))
        throw FeFileError(path, at, "node " + std::to_string(node) + ": the coordinate " + quoted(f[k]) +
                                        " is not finite");
    }
    NodeDofNumbers dofs{};
    for (int d = 0; d < 3; ++d) {
      long long number = 0;
      if (!parse_integer(f[2 + d], number))
        throw FeFileError(path, at, "node " + std::to_string(node) + ": the DOF number " + quoted(f[2 + d]) + " of " +
                                        dof_name(d) + " is not an integer");
      if (number < -1 || number >= num_dofs)
        throw FeFileError(path, at, "node " + std::to_string(node) + ": DOF number " + std::to_string(number) +
                                        " of " + dof_name(d) + " is outside the matrices (0 .. " +
                                        std::to_string(num_dofs - 1) + ", or -1 for none)");
      dofs[d] = static_cast<int>(number);
      if (number < 0) continue;
      const std::size_t i = static_cast<std::size_t>(number);
      if (owner_line[i] != 0)
        throw FeFileError(path, at, "node " + std::to_string(node) + ": DOF number " + std::to_string(number) +
                                        " of " + dof_name(d) + " is already used by " + dof_name(owner[i].second) +
                                        " of node " + std::to_string(owner[i].first) + " (line " +
                                        std::to_string(owner_line[i]) + ")");
      owner_line[i] = at;
      owner[i] = {node, d};
    }
    table.nodes.push_back(x);
    table.dofs.push_back(dofs);
  }
  if (table.nodes.empty()) throw FeFileError(path, 0, "the node table has no nodes");
  return table;
}

void write_node_table(const std::string& path, const NodeTable& table) {
  if (table.nodes.size() != table.dofs.size())
    throw std::invalid_argument("write_node_table: " + std::to_string(table.nodes.size()) + " nodes but " +
                                std::to_string(table.dofs.size()) + " DOF rows");
  std::string text = "# x y dof_ux dof_uy dof_psi\n";
  for (std::size_t k = 0; k < table.nodes.size(); ++k) {
    append_number(text, table.nodes[k].x());
    text += ' ';
    append_number(text, table.nodes[k].y());
    for (int d : table.dofs[k]) {
      text += ' ';
      append_number(text, static_cast<long long>(d));
    }
    text += '\n';
  }
  write_whole_file(path, text);
}

SparseFeModel load_sparse_fe_model(const std::string& mass_path, const std::string& stiffness_path,
                                   const std::string& nodes_path) {
  MarketFile mass = read_market(mass_path, MatrixShape::symmetric);
  MarketFile stiffness = read_market(stiffness_path, MatrixShape::symmetric);
  if (mass.A.rows() != stiffness.A.rows())
    throw FeFileError(stiffness_path, stiffness.size_line,
                      "K is " + std::to_string(stiffness.A.rows()) + " x " + std::to_string(stiffness.A.cols()) +
                          " but M (" + mass_path + ":" + std::to_string(mass.size_line) + ") is " +
                          std::to_string(mass.A.rows()) + " x " + std::to_string(mass.A.cols()) +
                          "; they must have the same size");
  SparseFeModel model;
  model.table = read_node_table(nodes_path, static_cast<int>(stiffness.A.rows()));
  model.M = std::move(mass.A);
  model.K = std::move(stiffness.A);
  return model;
}

}  // namespace fmbd
