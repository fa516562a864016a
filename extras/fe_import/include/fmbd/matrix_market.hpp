#pragma once
// External FE models: sparse matrices in Matrix Market files and a node table (module 5, given
// code). These are the forms in which common FE packages export their mass and stiffness matrices.
//
// Matrix Market (coordinate format, the subset read here):
//
//   %%MatrixMarket matrix coordinate real symmetric      <- line 1: header (case-insensitive);
//   % any number of comment lines                            field real or integer,
//   3 3 4                                                    symmetry symmetric or general
//   1 1 2.0                                              <- rows cols entries
//   2 1 -1.0                                             <- row col value, 1-based indices
//   2 2 2.0
//   3 3 1.0
//
// A `symmetric` file holds the lower triangle only (row >= col); each off-diagonal entry stands for
// itself and its mirror. A `general` file holds every non-zero. An index pair that occurs more than
// once is summed, as in FE assembly. Blank lines are skipped anywhere after the header.
//
// Node table (plain text, one line per node, node k on the k-th data line, counted from 0):
//
//   # x      y      dof_ux  dof_uy  dof_psi                 <- '#' starts a comment (to line end)
//   0.0      0.0    -1      -1      -1                       <- a clamped node: no DOF in the matrices
//   0.5      0.0     0       1       2
//   1.0      0.0     3       4       5
//
// x, y are the node's coordinates [m]; dof_* are the 0-based row numbers of its displacements u_x,
// u_y and rotation psi (the DOF order of fe_model.hpp) in the matrices, or -1 for a DOF that is not
// in them (fixed by a support, or one the element type does not have). Every row number may be used
// once. Rows of the matrices that no node names are allowed (for example internal DOFs).
//
// Every error in a file throws FeFileError; its message starts with "<path>:<line>: " (the line of
// the fault, counted from 1; the size line for an entry count that is too small).

#include <Eigen/SparseCore>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/fe_assembly.hpp"

namespace fmbd {

/// A malformed or inconsistent FE model file. what() is "<path>:<line>: <what is wrong>"; line 0
/// stands for the file as a whole (for example a file that cannot be opened).
class FeFileError : public std::runtime_error {
 public:
  FeFileError(const std::string& path, int line, const std::string& message);
  const std::string& path() const { return path_; }  ///< the file at fault
  int line() const { return line_; }                 ///< its line, from 1; 0 for the whole file

 private:
  std::string path_;
  int line_ = 0;
};

/// What read_matrix_market requires of the matrix beyond a well-formed file.
enum class MatrixShape {
  any,       ///< any rows x cols matrix
  symmetric  ///< square and symmetric: a `general` file must then be symmetric (see below)
};

/// Reads a Matrix Market coordinate file (format above). With MatrixShape::symmetric, a matrix
/// that is not square is an error at the size line, and a `general` file whose entries (i, j) and
/// (j, i) differ by more than 1e-10 max |a| is an error at the line of the first such entry;
/// within that bound it is made exactly symmetric, (A + A^T) / 2. Throws FeFileError for: a file
/// that cannot be read; a bad header (not `matrix coordinate real|integer general|symmetric`); a
/// missing or malformed size line (rows and cols 1 .. 10^8); an entry with the wrong number of
/// fields, text that is not a number, a value that is not finite, an index outside 1 .. rows or
/// 1 .. cols, or an entry above the diagonal of a `symmetric` file; more or fewer entries than the
/// size line declares.
SparseMat read_matrix_market(const std::string& path, MatrixShape shape = MatrixShape::any);

/// Writes a square symmetric matrix as `%%MatrixMarket matrix coordinate real symmetric`: the
/// lower triangle, column by column, values in the shortest form that reads back exactly. Throws
/// std::invalid_argument if A is not square, not finite or not symmetric (|a_ij - a_ji| > 1e-10
/// max |a|), and FeFileError if the file cannot be written.
void write_matrix_market(const std::string& path, const SparseMat& A);

/// The global DOF numbers of one node: (u_x, u_y, psi), -1 where a DOF is not in the matrices.
using NodeDofNumbers = std::array<int, 3>;

/// A node table: coordinates and DOF numbers of every node (format above).
struct NodeTable {
  std::vector<Vec2> nodes;              ///< coordinates of node k [m]
  std::vector<NodeDofNumbers> dofs;     ///< DOF numbers of node k
  int num_nodes() const { return static_cast<int>(nodes.size()); }
};

/// Reads a node table whose DOF numbers refer to matrices of size num_dofs x num_dofs. Throws
/// FeFileError for: a file that cannot be read; a line without exactly five fields; text that is
/// not a number (coordinates) or not an integer (DOF numbers); a coordinate that is not finite; a
/// DOF number outside -1 .. num_dofs - 1; a DOF number used twice (the message names both lines);
/// a table without nodes.
NodeTable read_node_table(const std::string& path, int num_dofs);

/// Writes a node table in the format above (with a comment line naming the columns). Throws
/// std::invalid_argument if nodes and dofs differ in length, FeFileError if the file cannot be
/// written.
void write_node_table(const std::string& path, const NodeTable& table);

/// An FE model read from files: sparse M and K with the node table that gives their DOFs a place.
struct SparseFeModel {
  SparseMat M;       ///< mass matrix (n x n, symmetric)
  SparseMat K;       ///< stiffness matrix (n x n, symmetric)
  NodeTable table;   ///< node coordinates and the DOF numbers of every node
  int num_dofs() const { return static_cast<int>(K.rows()); }
  int num_nodes() const { return table.num_nodes(); }
  /// Row of DOF d of node k in M and K, or -1 if that DOF is not in the matrices.
  int dof(int node, NodeDof d) const { return table.dofs.at(node)[static_cast<int>(d)]; }
};

/// Reads M and K (MatrixShape::symmetric each) and the node table. Throws FeFileError for any
/// fault of the three files (above) and if M and K differ in size (at the size line of the
/// stiffness file; the message names the mass file too).
SparseFeModel load_sparse_fe_model(const std::string& mass_path, const std::string& stiffness_path,
                                   const std::string& nodes_path);

}  // namespace fmbd
