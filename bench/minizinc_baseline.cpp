#include "minizinc_baseline.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace autonomy::bench {

std::optional<std::string> run_command(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string out;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  if (pclose(pipe) != 0) return std::nullopt;
  return out;
}

bool minizinc_with_gecode() {
  auto solvers = run_command("minizinc --solvers 2>/dev/null");
  if (!solvers) return false;
  std::string lower = *solvers;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  return lower.find("gecode") != std::string::npos;
}

// The data are written from the parsed instance (machines 1-based). With --intermediate and
// --output-time every improving solution is printed with "% time elapsed: <s> s" after it;
// "==========" ends the output when the search completed, i.e. the last solution is optimal.
Baseline run_minizinc(const std::string& model, const planner::JobShopInstance& inst,
                      const std::string& name, int seconds) {
  using Clock = std::chrono::steady_clock;
  Baseline b;
  const auto data = std::filesystem::temp_directory_path() / ("planner_bench_" + name + ".dzn");
  {
    std::ofstream out(data);
    out << "jobs = " << inst.jobs << ";\nmachines = " << inst.machines << ";\n";
    for (const char* what : {"machine", "duration"}) {
      out << what << " = [|";
      for (int j = 0; j < inst.jobs; ++j) {
        for (int k = 0; k < inst.machines; ++k) {
          const auto [m, d] = inst.operations[j][k];
          out << (k ? ", " : " ") << (what[0] == 'm' ? long(m + 1) : d);
        }
        out << " |";
      }
      out << "];\n";
    }
  }
  const auto start = Clock::now();
  auto out = run_command("minizinc --solver gecode --intermediate --output-time --statistics "
                         "--time-limit " +
                         std::to_string(seconds * 1000) + " '" + model + "' '" + data.string() +
                         "' 2>&1; true");  // a time-out is an answer too: read the output
  b.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::filesystem::remove(data);
  if (!out || out->find("makespan = ") == std::string::npos) return b;
  b.ran = true;
  b.proved = out->find("==========") != std::string::npos;
  for (std::size_t at = out->find("makespan = "); at != std::string::npos;
       at = out->find("makespan = ", at + 1)) {
    b.makespan = std::stol(out->substr(at + 11));
    const std::size_t t = out->find("% time elapsed: ", at);
    b.curve.push_back({t == std::string::npos ? b.seconds : std::stod(out->substr(t + 16)),
                       b.makespan});
  }
  if (auto at = out->find("solveTime="); at != std::string::npos)
    b.solve_seconds = std::stod(out->substr(at + 10));
  return b;
}

}  // namespace autonomy::bench
