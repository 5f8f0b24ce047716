// fosssim-study: runs the study's experiments and writes their CSV files (experiments.h).
// The charts and docs/study.md are made from those files by study/charts.py; scripts/study runs
// both. Usage (fosssim-study -h says more):
//   fosssim-study [--out DIR] [--quick] [--only accuracy,stability,robustness,hybrid,profile,contacts]
#include "experiments.h"

#include "cli_values.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <system_error>

int main(int argc, char** argv) {
  using namespace fosssim::study;
  struct Experiment {
    const char* name;
    fosssim::Status (*run)(const StudyOptions&);
  };
  const std::vector<Experiment> experiments = {{"accuracy", runAccuracy},     {"stability", runStability},
                                               {"robustness", runRobustness}, {"hybrid", runHybridCost},
                                               {"profile", runProfile},       {"contacts", runContacts}};
  std::vector<std::string> names;
  for (const Experiment& e : experiments) names.push_back(e.name);

  StudyOptions options;
  options.log = &std::cerr;
  std::vector<std::string> only = names;
  CLI::App app("Runs the study's experiments and writes their CSV files; study/charts.py and study/report.py\n"
               "make the charts and docs/study.md from them (scripts/study runs all three).",
               "fosssim-study");
  app.add_option("--out", options.outDir, "where the CSV files go (default: the current directory; created if needed)")
      ->option_text("DIR")
      ->check([](const std::string& dir) { return dir.empty() ? std::string("expected a folder, got \"\"") : ""; });
  app.add_flag("--quick", options.quick, "a tiny matrix of every experiment (seconds instead of minutes)");
  app.add_option("--only", only, "some of the experiments, comma-separated: accuracy, stability, robustness, hybrid, "
                                 "profile, contacts (default all)")
      ->delimiter(',')
      ->option_text("NAME,...")
      ->check(fosssim::cli::oneOf("experiment", names));
  if (const int status = fosssim::cli::parseCommandLine(app, argc, argv); status >= 0) return status;

  std::error_code error;
  std::filesystem::create_directories(options.outDir, error);
  if (error || !std::filesystem::is_directory(options.outDir)) {
    std::cerr << "fosssim-study: cannot create the folder " << options.outDir << ": "
              << (error ? error.message() : "a file of that name is in the way") << "\n";
    return 1;
  }
  for (const std::string& name : only) {
    const Experiment& e = *std::find_if(experiments.begin(), experiments.end(),
                                        [&](const Experiment& x) { return name == x.name; });  // names were checked
    const auto begin = std::chrono::steady_clock::now();
    if (fosssim::Status s = e.run(options); !s) {
      std::cerr << "fosssim-study: " << name << ": " << s.message() << "\n";
      return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::cerr << "fosssim-study: " << name << " done in " << static_cast<int>(seconds + 0.5) << " s\n";
  }
  return 0;
}
