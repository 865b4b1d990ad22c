#pragma once
// Every problem of a scene, gathered while the loader reads on past each one (a bad value
// leaves the key's default in place, so the keys after it are still checked), then thrown
// as one SceneError, a line a problem: "FILE: key 'K': what is wrong and what is allowed".
// Unknown keys are worded when the error is thrown, once every section has declared the
// keys it takes, so that a key in the wrong section is pointed to its own ("did you mean
// 'time.cfl'?"). A problem on a key that a --set gave names the --set.
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sphdem {

class SceneProblems {
 public:
  explicit SceneProblems(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  // A problem with the value at `key` (a dotted path; "" is the top level).
  void add(const std::string& key, const std::string& what);
  // A problem that is not about one key (the --set syntax, the YAML syntax): one line as is.
  void add_line(const std::string& line);
  // `key` is not one of `allowed`, the keys `section` takes.
  void unknown(const std::string& section, const std::string& key,
               const std::set<std::string>& allowed);
  // The keys `section` takes, for the hint on a key given in the wrong section.
  void declare(const std::string& section, const std::set<std::string>& keys);
  // A --set changed `path`: problems at or below it name the assignment.
  void override_applied(const std::string& path, const std::string& assignment);

  std::size_t count() const { return entries_.size(); }
  // One SceneError listing every problem so far; nothing when there is none.
  void throw_if_any() const;
  // A problem after which reading on makes no sense: adds it and throws them all.
  [[noreturn]] void stop(const std::string& key, const std::string& what);

 private:
  struct Entry {
    std::string line;     // a finished line, or empty for an unknown key
    std::string section;  // unknown key: its section, the key and the allowed keys there
    std::string key;
    std::vector<std::string> allowed;
  };
  std::string origin(const std::string& key) const;
  std::string unknown_line(const Entry& e,
                           const std::vector<std::pair<std::string, std::string>>& known) const;
  std::string file_;
  std::vector<Entry> entries_;
  std::vector<std::pair<std::string, std::set<std::string>>> sections_;
  std::vector<std::pair<std::string, std::string>> overrides_;  // path, assignment
};

}  // namespace sphdem
