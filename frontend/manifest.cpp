#include "manifest.hpp"

#include <cmath>

#include "file_io.hpp"
#include "json.hpp"

namespace fmbd::frontend {
namespace {

using json::Value;

// Reads the fields of the manifest, naming the file and the field in every error.
class Reader {
 public:
  explicit Reader(std::string origin) : origin_(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw ManifestError(origin_ + ": " + where + ": " + what);
  }

  const Value& member(const Value& object, const std::string& where, const std::string& key) const {
    const auto value = object.find(key);  // the callers have checked that `object` is one
    if (value == object.end()) fail(join(where, key), "missing");
    return *value;
  }

  // `value`, when it is of the kind of `kind` (any number for a number).
  const Value& of_kind(const Value& value, const std::string& where, Value::value_t kind) const {
    if (json::kind_name(value.type()) != json::kind_name(kind)) {
      fail(where, json::kind_name(kind) + " is expected, not " + json::kind_name(value.type()));
    }
    return value;
  }

  std::string string(const Value& object, const std::string& where, const std::string& key) const {
    return of_kind(member(object, where, key), join(where, key), Value::value_t::string).get<std::string>();
  }

  std::optional<std::string> optional_string(const Value& object, const std::string& where,
                                             const std::string& key) const {
    const auto value = object.find(key);
    if (value == object.end() || value->is_null()) return std::nullopt;
    return of_kind(*value, join(where, key), Value::value_t::string).get<std::string>();
  }

  int integer(const Value& object, const std::string& where, const std::string& key) const {
    const double number =
        of_kind(member(object, where, key), join(where, key), Value::value_t::number_float).get<double>();
    if (number != std::floor(number) || std::fabs(number) > 1e9) fail(join(where, key), "a whole number is expected");
    return static_cast<int>(number);
  }

  bool boolean(const Value& object, const std::string& where, const std::string& key) const {
    return of_kind(member(object, where, key), join(where, key), Value::value_t::boolean).get<bool>();
  }

  const Value& array(const Value& object, const std::string& where, const std::string& key) const {
    return of_kind(member(object, where, key), join(where, key), Value::value_t::array);
  }

  std::vector<std::string> strings(const Value& object, const std::string& where, const std::string& key) const {
    std::vector<std::string> out;
    const Value& items = array(object, where, key);
    for (std::size_t i = 0; i < items.size(); ++i) {
      out.push_back(of_kind(items[i], index(join(where, key), i), Value::value_t::string).get<std::string>());
    }
    return out;
  }

  static std::string join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
  }

  static std::string index(const std::string& where, std::size_t i) { return where + "[" + std::to_string(i) + "]"; }

  const std::string& origin() const { return origin_; }

 private:
  std::string origin_;
};

Module read_module(const Reader& r, const Value& item, const std::string& where) {
  r.of_kind(item, where, Value::value_t::object);
  Module module;
  module.number = r.integer(item, where, "number");
  module.id = r.string(item, where, "id");
  module.folder = r.string(item, where, "folder");
  module.exercises = r.strings(item, where, "exercises");
  module.hints = r.optional_string(item, where, "hints");
  module.student_library = r.string(item, where, "student_library");
  r.member(item, where, "reference_library");  // present, if only as null
  module.reference_library = r.optional_string(item, where, "reference_library");
  return module;
}

// The capabilities of a graded item (the schema in manifest.hpp).
void read_capabilities(const Reader& r, const Value& item, const std::string& where, GradedItem& graded) {
  graded.inputs = r.strings(item, where, "inputs");
  graded.needs_identity = r.boolean(item, where, "needs_identity");
  graded.links_student_code = r.boolean(item, where, "links_student_code");
  graded.classroom = r.boolean(item, where, "classroom");
  const std::string without_reference = r.string(item, where, "without_reference");
  if (without_reference == "all") {
    graded.without_reference = WithoutReference::all;
  } else if (without_reference == "format") {
    graded.without_reference = WithoutReference::format;
  } else {
    r.fail(Reader::join(where, "without_reference"), "\"all\" or \"format\" is expected, not \"" + without_reference + "\"");
  }
}

GradedItem read_graded(const Reader& r, const Value& item, const std::string& where) {
  r.of_kind(item, where, Value::value_t::object);
  GradedItem graded;
  graded.id = r.string(item, where, "id");
  graded.kind = r.string(item, where, "kind");
  graded.module = r.integer(item, where, "module");
  graded.program = r.string(item, where, "program");
  graded.target = r.string(item, where, "target");
  r.member(item, where, "reference_program");  // present, if only as null
  r.member(item, where, "reference_target");
  graded.reference_program = r.optional_string(item, where, "reference_program");
  graded.reference_target = r.optional_string(item, where, "reference_target");
  r.member(item, where, "vet_target");
  r.member(item, where, "vet_report");
  graded.vet_target = r.optional_string(item, where, "vet_target");
  graded.vet_report = r.optional_string(item, where, "vet_report");
  if (graded.vet_target.has_value() != graded.vet_report.has_value()) {
    r.fail(Reader::join(where, "vet_report"), "vet_target and vet_report are both null or both given");
  }
  read_capabilities(r, item, where, graded);
  return graded;
}

Program read_program(const Reader& r, const Value& item, const std::string& where) {
  r.of_kind(item, where, Value::value_t::object);
  return Program{r.string(item, where, "name"), r.string(item, where, "target"), r.string(item, where, "program")};
}

}  // namespace

std::optional<bool> has_capability(const GradedItem& item, std::string_view name) {
  if (name == "inputs") return !item.inputs.empty();
  if (name == "needs_identity") return item.needs_identity;
  if (name == "links_student_code") return item.links_student_code;
  if (name == "classroom") return item.classroom;
  return std::nullopt;
}

const Module* Manifest::module(int number) const {
  for (const Module& m : modules) {
    if (m.number == number) return &m;
  }
  return nullptr;
}

Manifest parse_manifest(std::string_view text, const std::string& origin) {
  Value document;
  try {
    document = json::parse(text);
  } catch (const json::ParseError& error) {
    throw ManifestError(origin + ": " + error.what());
  }
  const Reader r(origin);
  r.of_kind(document, "the document", Value::value_t::object);
  Manifest manifest;
  manifest.schema = r.integer(document, "", "schema");
  if (manifest.schema < kManifestSchema) {
    throw OlderManifest(origin + ": schema: schema " + std::to_string(manifest.schema) +
                            " is older than the one this front end reads (" + std::to_string(kManifestSchema) +
                            "); configure the build again",
                        manifest.schema);
  }
  if (manifest.schema != kManifestSchema) {
    r.fail("schema", "schema " + std::to_string(manifest.schema) + " is newer than the one this front end reads (" +
                         std::to_string(kManifestSchema) + "); build the front end of the same tree");
  }
  manifest.source_dir = r.string(document, "", "source_dir");
  manifest.build_dir = r.string(document, "", "build_dir");
  r.member(document, "", "grade_driver");
  manifest.grade_driver = r.optional_string(document, "", "grade_driver").value_or("");
  manifest.instructor = r.boolean(document, "", "instructor");
  r.member(document, "", "release_policy");
  manifest.release_policy = r.optional_string(document, "", "release_policy");
  const Value& modules = r.array(document, "", "modules");
  for (std::size_t i = 0; i < modules.size(); ++i) {
    manifest.modules.push_back(read_module(r, modules[i], Reader::index("modules", i)));
  }
  const Value& graded = r.array(document, "", "graded");
  for (std::size_t i = 0; i < graded.size(); ++i) {
    manifest.graded.push_back(read_graded(r, graded[i], Reader::index("graded", i)));
  }
  const Value& demos = r.array(document, "", "demos");
  for (std::size_t i = 0; i < demos.size(); ++i) {
    manifest.demos.push_back(read_program(r, demos[i], Reader::index("demos", i)));
  }
  const Value& benchmarks = r.array(document, "", "benchmarks");
  for (std::size_t i = 0; i < benchmarks.size(); ++i) {
    manifest.benchmarks.push_back(read_program(r, benchmarks[i], Reader::index("benchmarks", i)));
  }
  return manifest;
}

Manifest read_manifest(const std::string& path) {
  std::string text;
  if (!fmbd::tools::read_file(path, text)) {
    throw ManifestError(path + ": cannot be read (configure the build: it writes the course manifest)");
  }
  return parse_manifest(text, path);
}

}  // namespace fmbd::frontend
