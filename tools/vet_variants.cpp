// fmbd-vet-variants: writes the legal variant of a reference solution file that the source check
// must accept (the test mNN.vet_passes_legal_variants).
//
//   fmbd-vet-variants [--course-types] --nm NM --object OBJECT SOLUTION OUT
//
// The task functions are those whose stub throws NotImplemented("MnnTk NAME") in SOLUTION; their
// exact signatures are read from the compiled reference OBJECT (`NM -C --defined-only`), so that
// every overload counts and nothing is listed by hand. OUT is SOLUTION followed by one function
// per signature, inside namespace fmbd, of that same signature: it calls the task function
// through a std::function made from its pointer, from a lambda that captures the std::function and,
// with --course-types (a course whose module 1 declares them), the course's types MatX, VecX, Vec3
// and a Model. The compiler then emits the weak typeinfo of
// the function type and of its pointer, and std::function's and the lambda's instantiations over
// the course's types: its own data, which a legal submission may hold.
//
// Exit status: 0 written, 1 a task function has no signature in OBJECT, 2 usage or I/O error.

#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "file_io.hpp"
#include "process.hpp"
#include "strings.hpp"
#include "task_id.hpp"

namespace {

struct Signature {
  std::string name;                 // the task function, in namespace fmbd
  std::vector<std::string> params;  // demangled parameter types
};

// The NAMEs of the NotImplemented("MnnTk NAME") stubs of a solution file.
std::set<std::string> task_functions(const std::string& solution) {
  std::set<std::string> names;
  const std::string marker = "NotImplemented(\"";
  for (std::size_t at = solution.find(marker); at != std::string::npos; at = solution.find(marker, at + 1)) {
    const std::size_t start = at + marker.size();
    const std::size_t end = solution.find('"', start);
    std::istringstream words(solution.substr(start, end - start));
    std::string id, name;
    if (words >> id >> name && fmbd::protocol::parse_task_id(id)) names.insert(name);
  }
  return names;
}

// The top-level comma-separated parts of `list` (template arguments and nested parentheses kept).
std::vector<std::string> split_params(const std::string& list) {
  std::vector<std::string> params;
  int depth = 0;
  std::string current;
  for (const char c : list) {
    if (c == '<' || c == '(' || c == '[') ++depth;
    if (c == '>' || c == ')' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      params.push_back(fmbd::tools::trim(current));
      current.clear();
    } else {
      current += c;
    }
  }
  if (!fmbd::tools::trim(current).empty()) params.push_back(fmbd::tools::trim(current));
  if (params.size() == 1 && params[0] == "void") params.clear();
  return params;
}

// "fmbd::NAME[abi:cxx11](PARAMS)" -> the signature, when NAME is a task function.
bool parse_definition(const std::string& demangled, const std::set<std::string>& names, Signature& out) {
  if (!fmbd::tools::starts_with(demangled, "fmbd::")) return false;
  const std::size_t open = demangled.find('(');
  if (open == std::string::npos || demangled.back() != ')') return false;
  std::string name = demangled.substr(6, open - 6);
  const std::size_t tag = name.find("[abi:");
  if (tag != std::string::npos) name.erase(tag);
  if (!names.count(name)) return false;
  out.name = name;
  out.params = split_params(demangled.substr(open + 1, demangled.size() - open - 2));
  return true;
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? separator : "") + parts[i];
  return text;
}

// One probe of `signature`, named fmbd::vet_variant_STEM_K.
std::string probe(const Signature& signature, const std::string& stem, std::size_t k, bool course_types) {
  const std::string id = stem + "_" + std::to_string(k);
  std::vector<std::string> declvals, params, lambda_params, forwarded, lambda_forwarded;
  if (course_types) params.push_back("const Model& model");
  for (std::size_t i = 0; i < signature.params.size(); ++i) {
    const std::string& type = signature.params[i];
    declvals.push_back("std::declval<" + type + ">()");
    params.push_back(type + " a" + std::to_string(i));
    lambda_params.push_back(type + " b" + std::to_string(i));
    forwarded.push_back("std::forward<" + type + ">(a" + std::to_string(i) + ")");
    lambda_forwarded.push_back("std::forward<" + type + ">(b" + std::to_string(i) + ")");
  }
  std::ostringstream out;
  out << "using Result_" << id << " = decltype(::fmbd::" << signature.name << "(" << joined(declvals, ", ") << "));\n"
      << "using Signature_" << id << " = Result_" << id << "(" << joined(signature.params, ", ") << ");\n"
      << "Result_" << id << " vet_variant_" << id << "(" << joined(params, ", ") << ") {\n"
      << "  const std::function<Signature_" << id << "> through_function = static_cast<Signature_" << id
      << "*>(&::fmbd::" << signature.name << ");\n";
  if (course_types) {
    out << "  const MatX block = MatX::Identity(2, 2);\n"
        << "  const VecX values = VecX::Ones(2);\n"
        << "  const Vec3 pose = Vec3::Zero();\n"
        << "  const auto through_lambda = [through_function, block, values, pose, &model](" << joined(lambda_params, ", ")
        << ") -> Result_" << id << " {\n"
        << "    if (block.size() + values.size() + pose.size() < model.num_coordinates()) throw std::logic_error(\"unused\");\n";
  } else {
    out << "  const auto through_lambda = [through_function](" << joined(lambda_params, ", ") << ") -> Result_" << id
        << " {\n";
  }
  out << "    return through_function(" << joined(lambda_forwarded, ", ") << ");\n"
      << "  };\n"
      << "  return through_lambda(" << joined(forwarded, ", ") << ");\n"
      << "}\n";
  return out.str();
}

// The command line (its usage comes from this table).
fmbd::cli::Command command_line() {
  using fmbd::cli::Kind;
  return fmbd::cli::program("fmbd-vet-variants",
                            {{"--course-types", Kind::flag, "", "", ""},
                             {"--nm", Kind::value, "NM", "a program", ""},
                             {"--object", Kind::value, "OBJECT", "a file name", ""}},
                            "FILE", 2, "[--course-types] --nm NM --object OBJECT SOLUTION OUT");
}

}  // namespace

int main(int argc, char** argv) {
  const fmbd::cli::Command command = command_line();
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  if (!parsed.has("--nm") || !parsed.has("--object") || parsed.positionals.size() != 2) {
    std::cerr << fmbd::cli::program_usage(command);
    return 2;
  }
  const bool course_types = parsed.has("--course-types");
  const std::string nm = parsed.value("--nm"), object = parsed.value("--object");
  const std::string &solution_path = parsed.positionals[0], &out_path = parsed.positionals[1];
  std::string solution;
  if (!fmbd::tools::read_file(solution_path, solution)) {
    std::cerr << "fmbd-vet-variants: cannot read " << solution_path << "\n";
    return 2;
  }
  const std::set<std::string> names = task_functions(solution);
  int status = 0;
  const std::string symbols = fmbd::tools::capture(fmbd::tools::Command({nm, "-C", "--defined-only", object}), status);
  if (status != 0) {
    std::cerr << "fmbd-vet-variants: " << nm << " could not read " << object << "\n";
    return 2;
  }
  std::vector<Signature> signatures;
  std::set<std::string> found;
  for (const std::string& line : fmbd::tools::split_lines(symbols)) {
    // "VALUE T fmbd::NAME(PARAMS)": strong text symbols, the functions the file defines.
    const std::size_t type = line.find(" T ");
    if (type == std::string::npos || line.find(' ') != type) continue;
    Signature signature;
    if (parse_definition(line.substr(type + 3), names, signature)) {
      found.insert(signature.name);
      signatures.push_back(signature);
    }
  }
  for (const std::string& name : names) {
    if (!found.count(name)) {
      std::cerr << "fmbd-vet-variants: " << solution_path << ": the task function " << name << " is not defined in "
                << object << "\n";
      return 1;
    }
  }
  std::string stem = out_path.substr(out_path.find_last_of('/') + 1);
  stem = stem.substr(0, stem.find('.'));
  std::string variant = solution +
                        "\n// The legal variant (tools/vet_variants.cpp): every task function through a\n"
                        "// std::function of its exact signature and a lambda that captures the course's types.\n"
                        "#include <functional>\n#include <stdexcept>\n#include <utility>\n\n" +
                        std::string(course_types ? "#include \"fmbd/model.hpp\"\n#include \"fmbd/planar.hpp\"\n\n" : "") +
                        "namespace fmbd {\n\n";
  for (std::size_t k = 0; k < signatures.size(); ++k) variant += probe(signatures[k], stem, k, course_types) + "\n";
  variant += "}  // namespace fmbd\n";
  if (!fmbd::tools::write_if_changed(out_path, variant)) {
    std::cerr << "fmbd-vet-variants: cannot write " << out_path << "\n";
    return 2;
  }
  std::cout << out_path << ": " << signatures.size() << " signatures of " << names.size() << " task functions\n";
  return 0;
}
