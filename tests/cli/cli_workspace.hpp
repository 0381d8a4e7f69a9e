#pragma once
// What the end-to-end tests of the `rollnoise` program share: files, a fresh folder per test
// (Workspace), and running the built program (ROLLNOISE_BINARY) in it as a user would, with
// stdin from /dev/null and stdout and stderr captured.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cli_test {
namespace fs = std::filesystem;

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

inline void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  ASSERT_TRUE(out) << "cannot write " << path;
}

inline std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline std::size_t count_lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

inline bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

inline bool gnuplot_installed() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

struct RunResult {
  int status = -1;  // the exit status; 128 + signal when the program was killed by a signal
  std::string out;
  std::string err;
};

// A fresh folder under the system's temp folder, removed at the end of the test. The program
// runs in work(); its stdout and stderr are captured beside work(), so that work() holds only
// what the test wrote and what the program made.
class Workspace {
 public:
  Workspace() {
    static std::atomic<int> counter{0};
    std::string name = "rollnoise_cli_";
    if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info()) {
      name += info->test_suite_name();
      name += '_';
      name += info->name();
    }
    for (char& c : name) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
    }
    name += '_';
    name += std::to_string(::getpid());
    name += '_';
    name += std::to_string(counter++);
    root_ = fs::temp_directory_path() / name;
    fs::remove_all(root_);
    fs::create_directories(root_ / "work");
  }
  ~Workspace() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  fs::path work() const { return root_ / "work"; }
  fs::path path(const std::string& name) const { return work() / name; }
  void write(const std::string& name, const std::string& text) const { write_text(path(name), text); }

  // Runs `prefix ROLLNOISE_BINARY args...` in work(), stdin from /dev/null.
  RunResult run(const std::vector<std::string>& args, const std::string& prefix = "") const {
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on `" " + std::string` here.
    std::string command = "cd ";
    command += shell_quote(work().string());
    command += " && ";
    command += prefix;
    command += shell_quote(ROLLNOISE_BINARY);
    for (const auto& arg : args) {
      command += ' ';
      command += shell_quote(arg);
    }
    command += " </dev/null >";
    command += shell_quote((root_ / "stdout.txt").string());
    command += " 2>";
    command += shell_quote((root_ / "stderr.txt").string());
    const int raw = std::system(command.c_str());
    RunResult result;
    if (raw != -1 && WIFEXITED(raw)) result.status = WEXITSTATUS(raw);
    if (raw != -1 && WIFSIGNALED(raw)) result.status = 128 + WTERMSIG(raw);
    result.out = read_text(root_ / "stdout.txt");
    result.err = read_text(root_ / "stderr.txt");
    return result;
  }

  // Names in work(), hidden ones included, with "/" after folders; recursive, so that a folder
  // left behind anywhere shows.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(work())) {
      names.insert(fs::relative(entry.path(), work()).string() + (entry.is_directory() ? "/" : ""));
    }
    return names;
  }

  // Hidden staging or backup folders (".NAME.partial-PID", ".NAME.old-PID") in work().
  std::vector<std::string> leftovers() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(work())) {
      const std::string name = entry.path().filename().string();
      if (starts_with(name, ".")) names.push_back(name);
    }
    return names;
  }

 private:
  fs::path root_;
};

inline std::string describe(const RunResult& r) {
  // (Built with a stream: GCC 12 warns falsely, -Wrestrict, on chains of string + string.)
  std::ostringstream s;
  s << "exit status " << r.status << "\n--- stderr ---\n" << r.err << "--- stdout ---\n" << r.out;
  return s.str();
}

inline nlohmann::json read_json(const fs::path& path) {
  const std::string text = read_text(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    ADD_FAILURE() << path << " is not valid JSON: " << error.what() << "\n" << text;
    return nlohmann::json::object();
  }
}

inline std::string first_line(const fs::path& path) {
  std::istringstream in(read_text(path));
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace cli_test
