#include "report.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>

#include "csv.hpp"
#include "json.hpp"
#include "tables.hpp"
#include "task_id.hpp"
#include "text.hpp"

namespace fmbd::grade {
namespace {

constexpr std::size_t kTableWidth = 72;

double earned(const TestResult& result) { return result.passed ? result.test.points : 0; }

// Points and seconds in results.json: to a thousandth, as the score table prints them.
json::Value thousandths(double value) { return json::whole_or_fraction(std::round(value * 1000) / 1000); }

std::string fraction(double score, double max_score) {
  return format_number(score) + "/" + format_number(max_score);
}

std::string pad_left(const std::string& text, std::size_t width) {
  return std::string(width - std::min(width, text.size()), ' ') + text;
}

// Calls `visit(module_label, first, last)` for each run of results in the same module.
template <typename Visitor>
void for_each_module(const std::vector<TestResult>& results, Visitor visit) {
  for (auto first = results.begin(); first != results.end();) {
    const std::string label = module_label(first->test.module);
    const auto last = std::find_if(first, results.end(), [&label](const TestResult& result) {
      return module_label(result.test.module) != label;
    });
    visit(label, first, last);
    first = last;
  }
}

Totals totals(std::vector<TestResult>::const_iterator first,
              std::vector<TestResult>::const_iterator last) {
  Totals sum;
  for (auto it = first; it != last; ++it) {
    sum.score += earned(*it);
    sum.max_score += it->test.points;
    ++(it->passed ? sum.passed : sum.failed);
  }
  return sum;
}

std::string test_output(const TestResult& result) {
  if (result.passed) return result.output;
  const std::string head = result.rerun.empty() ? result.reason : result.reason + "\nrun it alone: " + result.rerun;
  return result.output.empty() ? head : head + "\n\n" + result.output;
}

std::string class_name(const TestCase& test) {
  const std::string module = module_label(test.module);
  return test.task ? module + "." + task_label(test.task) : module;
}

}  // namespace

const char* status_name(Status status) {
  switch (status) {
    case Status::passed: return "passed";
    case Status::failed: return "failed";
    case Status::not_implemented: return "not_implemented";
    case Status::crashed: return "crashed";
    case Status::timed_out: return "timed_out";
    case Status::rejected: return "rejected";
    case Status::build_error: return "build_error";
  }
  return "failed";
}

Totals totals(const std::vector<TestResult>& results) {
  return totals(results.begin(), results.end());
}

std::string format_table(const std::vector<TestResult>& results, bool failures_only) {
  std::size_t points_width = 0;
  for (const TestResult& result : results)
    points_width = std::max(points_width, fraction(earned(result), result.test.points).size());

  // "label  ......  score" lines for a module (indent 0) and a task (indent 2).
  const auto subtotal = [](const std::string& label, std::size_t indent, const Totals& sum) {
    const std::string score = fraction(sum.score, sum.max_score);
    const std::size_t used = indent + label.size() + score.size() + 4;
    const std::size_t dots = std::max<std::size_t>(3, kTableWidth - std::min(kTableWidth, used));
    return std::string(indent, ' ') + label + "  " + std::string(dots, '.') + "  " + score + "\n";
  };

  std::string table;
  for_each_module(results, [&](const std::string& module, auto first, auto last) {
    if (!failures_only) table += subtotal(module, 0, totals(first, last));
    for (auto task_first = first; task_first != last;) {
      const auto task_last = std::find_if(task_first, last, [&](const TestResult& result) {
        return result.test.task != task_first->test.task;
      });
      const std::string task = task_label(task_first->test.task);
      if (!failures_only) table += subtotal(task, 2, totals(task_first, task_last));
      for (auto it = task_first; it != task_last; ++it) {
        if (failures_only && it->passed) continue;
        table += failures_only ? "  " + module + " " + task + "  " : std::string(6, ' ');
        table += pad_left(fraction(earned(*it), it->test.points), points_width) + "  " +
                 (it->passed ? "PASS" : "FAIL") + "  " + (it->test.hidden ? "(hidden) " : "") +
                 single_line(it->test.name);
        if (!it->passed) table += "  -- " + it->reason;
        table += "\n";
        if (!it->passed && !it->rerun.empty()) table += std::string(8, ' ') + "run it alone: " + it->rerun + "\n";
      }
      task_first = task_last;
    }
  });
  const Totals all = totals(results);
  table += "Score: " + fraction(all.score, all.max_score) + "\n";
  return table;
}

std::string earlier_stubs_line(const std::vector<TestResult>& results, const std::string& advice) {
  constexpr std::string_view kStub = "not implemented yet: ";
  std::vector<std::string> modules;
  std::vector<std::string> tasks;
  const auto add = [](std::vector<std::string>& list, const std::string& item) {
    if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
  };
  for (const TestResult& result : results) {
    const std::size_t at = result.reason.find(kStub);
    if (result.passed || !result.test.module || at == std::string::npos) continue;
    const std::string rest = result.reason.substr(at + kStub.size());
    const std::optional<protocol::TaskId> stub = protocol::parse_task_id(rest.substr(0, rest.find_first_of(" ;,)")));
    if (!stub || stub->module >= *result.test.module) continue;
    add(modules, module_label(result.test.module));
    add(tasks, protocol::format_task_id(*stub));
  }
  if (tasks.empty()) return "";
  std::sort(tasks.begin(), tasks.end());
  const auto listed = [](const std::vector<std::string>& list) {
    std::string text;
    for (const std::string& item : list) text += (text.empty() ? "" : ", ") + item;
    return text;
  };
  return "Tests of " + listed(modules) + " failed on earlier modules' tasks not implemented yet: " + listed(tasks) +
         "." + (advice.empty() ? "" : " " + advice) + "\n";
}

std::string gradescope_json(const std::vector<TestResult>& results, double seconds,
                            const std::string& hidden_visibility,
                            const std::vector<std::string>& notes) {
  const Totals all = totals(results);
  std::string summary = std::to_string(all.passed) + " of " + std::to_string(results.size()) +
                        " tests passed; score " + fraction(all.score, all.max_score) + ".";
  if (std::any_of(results.begin(), results.end(),
                  [](const TestResult& r) { return r.test.hidden; })) {
    if (hidden_visibility == "after_published") {
      summary += " Hidden tests are shown once the grades are published.";
    } else if (hidden_visibility == "after_due_date") {
      summary += " Hidden tests are shown after the due date.";
    } else if (hidden_visibility == "hidden") {
      summary += " Hidden tests count but are not shown.";
    }
  }

  for (const std::string& note : notes) summary += "\n" + note;

  json::Value tests = json::Value::array();
  for (const TestResult& result : results) {
    json::Value tags = json::Value::array();
    if (result.test.module) tags.push_back(module_label(result.test.module));
    if (result.test.task) tags.push_back(task_label(result.test.task));
    tests.push_back({{"name", result.test.name},
                     {"score", thousandths(earned(result))},
                     {"max_score", thousandths(result.test.points)},
                     {"status", result.passed ? "passed" : "failed"},
                     {"output", test_output(result)},
                     {"tags", std::move(tags)},
                     {"visibility", result.test.hidden ? hidden_visibility : "visible"}});
  }
  return json::write({{"score", thousandths(all.score)},
                      {"max_score", thousandths(all.max_score)},
                      {"execution_time", thousandths(seconds)},
                      {"output", summary},
                      {"stdout_visibility", "hidden"},
                      {"tests", std::move(tests)}}) +
         "\n";
}

std::string failed_results_json(const std::string& output) {
  return json::write({{"score", 0},
                      {"output", output},
                      {"stdout_visibility", "hidden"},
                      {"tests", json::Value::array()}}) +
         "\n";
}

std::string junit_xml(const std::vector<TestResult>& results, double seconds) {
  const Totals all = totals(results);
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuites name=\"fmbd-grade\" tests=\"" + std::to_string(results.size()) +
         "\" failures=\"" + std::to_string(all.failed) + "\" errors=\"0\" time=\"" +
         format_seconds(seconds) + "\">\n";
  for_each_module(results, [&xml](const std::string& module, auto first, auto last) {
    const Totals suite = totals(first, last);
    double suite_seconds = 0;
    for (auto it = first; it != last; ++it) suite_seconds += it->seconds;
    xml += "  <testsuite name=\"" + xml_attribute(module) + "\" tests=\"" +
           std::to_string(suite.passed + suite.failed) + "\" failures=\"" +
           std::to_string(suite.failed) + "\" errors=\"0\" skipped=\"0\" time=\"" +
           format_seconds(suite_seconds) + "\">\n";
    for (auto it = first; it != last; ++it) {
      xml += "    <testcase classname=\"" + xml_attribute(class_name(it->test)) + "\" name=\"" +
             xml_attribute(it->test.name) + "\" time=\"" + format_seconds(it->seconds) + "\"";
      if (it->passed) {
        xml += "/>\n";
      } else {
        xml += ">\n      <failure type=\"" + std::string(status_name(it->status)) + "\" message=\"" +
               xml_attribute(it->reason) + "\">" +
               xml_text(it->output) + "</failure>\n    </testcase>\n";
      }
    }
    xml += "  </testsuite>\n";
  });
  xml += "</testsuites>\n";
  return xml;
}

std::string task_csv(const std::vector<TestResult>& results) {
  std::vector<TaskRow> rows;
  for (auto first = results.begin(); first != results.end();) {
    const auto last = std::find_if(first, results.end(), [&first](const TestResult& r) {
      return r.test.module != first->test.module || r.test.task != first->test.task;
    });
    const Totals sum = totals(first, last);
    const Status worst = std::max_element(first, last, [](const TestResult& a, const TestResult& b) {
                           return a.status < b.status;
                         })->status;
    rows.push_back({module_label(first->test.module), task_label(first->test.task), sum.score, sum.max_score,
                    status_name(worst)});
    first = last;
  }
  return tasks_csv_text(rows);
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ignored;  // a folder that cannot be made shows as the failure to write below
  if (!parent.empty()) std::filesystem::create_directories(parent, ignored);
  std::string temporary = path + ".XXXXXX";
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) {
    throw std::system_error(errno, std::generic_category(), "cannot write " + path);
  }
  const auto fail = [&](const std::string& what) {
    const int error = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    throw std::system_error(error, std::generic_category(), what);
  };
  if (::fchmod(fd, 0644) != 0) fail("cannot set the permissions of " + temporary);
  for (std::size_t done = 0; done < content.size();) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("cannot write " + temporary);
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("cannot write " + temporary);
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw std::system_error(error, std::generic_category(), "cannot write " + temporary);
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw std::system_error(error, std::generic_category(),
                            "cannot rename " + temporary + " to " + path);
  }
}

}  // namespace fmbd::grade
