// Fuzz target: study files (study/study_file.hpp): [study], [set], [vary], and the base case and
// library files they name, whose keys the reader checks. The input is written as a study in a
// folder beside which `cases`, `surfaces` and `tyres` lead to models/ (the working folder is the
// source tree, as for ctest's replay and tools/fuzz.sh), so the examples' "../cases/…" resolve.
#include <unistd.h>

#include "fuzz_target.hpp"
#include "study/study_file.hpp"

namespace {

// <temp>/rollnoise_fuzz_study_<pid>/{studies/input.toml, cases, surfaces, tyres}; removed at exit.
class StudyFolder {
 public:
  StudyFolder()
      : root_(std::filesystem::temp_directory_path() / ("rollnoise_fuzz_study_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(root_ / "studies");
    const std::filesystem::path models = std::filesystem::current_path() / "models";
    for (const char* name : {"cases", "surfaces", "tyres"}) {
      std::error_code ec;
      std::filesystem::create_directory_symlink(models / name, root_ / name, ec);
    }
  }
  ~StudyFolder() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  StudyFolder(const StudyFolder&) = delete;
  StudyFolder& operator=(const StudyFolder&) = delete;
  std::filesystem::path study() const { return root_ / "studies" / "input.toml"; }

 private:
  std::filesystem::path root_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollnoise;
  static const StudyFolder folder;
  {
    std::ofstream out(folder.study(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  return fuzz::guarded([&] {
    const StudySpec spec = read_study_file(folder.study());
    (void)spec.case_count();
  });
}
