// The typed DDS layer (common/dds: Writer<T>, Reader<T>, WaitSet, conversions) against the raw
// Cyclone C API, measured in the same run and the same topology: this process and one helper
// process (this binary re-executed with --child) on loopback, reliable QoS, waitset-driven.
//
//   round trip: ping here, echo there; RobotState (the lockstep's largest per-tick sample) and a
//               1 KiB blob; p50 / p90 / p99 in us.
//   throughput: 1 KiB blobs, reliable keep-last 256, written back to back here, counted there.
//
// Raw and layer runs alternate over several rounds so that drift of the machine hits both.
// Prints figures and the ratio layer/raw; the goal is a ratio of at most 1.20.
//
// Usage: dds_layer_bench [--domain 160] [--rounds 3] [--count 5000] [--warmup 500]
//                        [--tp-seconds 2] [--quick] [--secure-domain N]
// Needs CYCLONEDDS_URI (bench/run.sh uses deploy/dds/loopback.xml).
//
// --secure-domain N: DDS Security's cost instead. The typed layer on --domain (plain) against the
// typed layer on domain N, which CYCLONEDDS_URI must secure (deploy/security/security.sh uri DIR
// NAME --domain N, an identity granted 'bench/*'; bench/run.sh --secure makes one): the same
// round trips and throughput, plain and secured alternating, ratios secured/plain.
#include "bench/bench_support.hpp"
#include "bench/pingpong.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace autonomy::bench;

namespace {

int child_main(int argc, char** argv) {
  // --child echo API PAYLOAD DOMAIN TAG | --child tp-read API DOMAIN TAG
  const std::string role = argv[2];
  if (role == "echo" && argc == 7) {
    echo(parse_api(argv[3]), parse_payload(argv[4]), std::atoi(argv[5]), argv[6]);
    return 0;
  }
  if (role == "tp-read" && argc == 6) {
    const ReaderStats st = throughput_read(parse_api(argv[3]), std::atoi(argv[4]), argv[5]);
    std::printf("%llu %.9f %llu\n", static_cast<unsigned long long>(st.received), st.seconds,
                static_cast<unsigned long long>(st.lost));
    return 0;
  }
  std::fprintf(stderr, "bad --child arguments\n");
  return 2;
}

struct Options {
  int domain = 160;
  int rounds = 3;
  int count = 5000;
  int warmup = 500;
  double tp_seconds = 2.0;
  int secure_domain = -1;
};

// Exits (help text or argument error, CLI11's exit code) when the arguments do not make a run.
Options parse(int argc, char** argv) {
  Options o;
  bool quick = false;
  CLI::App app{"Typed DDS layer against the raw Cyclone C API: round trips, throughput, CPU per sample"};
  app.add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232))->capture_default_str();
  app.add_option("--rounds", o.rounds, "Alternating raw/layer rounds")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--count", o.count, "Round trips per run")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--warmup", o.warmup, "Warm-up round trips")->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_option("--tp-seconds", o.tp_seconds, "Seconds per throughput run")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--secure-domain", o.secure_domain,
                 "Compare plain --domain against this domain, secured by CYCLONEDDS_URI (DDS Security)")
      ->check(CLI::Range(0, 230));
  app.add_flag("--quick", quick, "Short runs, for a smoke test (1 round, 1000 round trips, 0.5 s)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e));
  }
  if (quick) {
    o.rounds = 1;
    o.count = 1000;
    o.tp_seconds = 0.5;
  }
  return o;
}

void print_rtt_row(const char* payload, const char* api, const std::vector<double>& v) {
  std::printf("  %-11s %-6s %8zu %9.1f %9.1f %9.1f %9.1f\n", payload, api, v.size(), percentile(v, 50),
              percentile(v, 90), percentile(v, 99), mean(v));
}

// The typed layer plain (o.domain) against secured (o.secure_domain): round trips and throughput,
// the two alternating within every round so that drift of the machine hits both.
int secure_main(const Options& o, const std::string& exe) {
  const Payload payloads[] = {Payload::RobotState, Payload::Blob1K};
  const int domains[2] = {o.domain, o.secure_domain};
  const char* names[2] = {"plain", "secure"};
  std::map<std::pair<Payload, int>, std::vector<double>> rtt;
  std::map<int, std::vector<double>> recv_rate;
  std::map<int, uint64_t> lost;
  int run = 0;
  for (int round = 0; round < o.rounds; ++round) {
    for (Payload payload : payloads) {
      for (int k = 0; k < 2; ++k) {
        const int which = round % 2 == 0 ? k : 1 - k;
        const std::string tag = std::string(to_string(payload)) + "_" + names[which] + "_" + std::to_string(run++);
        ChildProcess echo_side({exe, "--child", "echo", "layer", to_string(payload), std::to_string(domains[which]), tag},
                               false);
        std::vector<double> v = ping(Api::Layer, payload, domains[which], tag, o.warmup, o.count);
        if (echo_side.wait(std::chrono::seconds(10)) != 0) throw std::runtime_error("echo process failed");
        progress("[rtt round %d/%d] %-10s %-6s p50 %.1f us  p99 %.1f us", round + 1, o.rounds, to_string(payload),
                 names[which], percentile(v, 50), percentile(v, 99));
        auto& all = rtt[{payload, which}];
        all.insert(all.end(), v.begin(), v.end());
      }
    }
    for (int k = 0; k < 2; ++k) {
      const int which = round % 2 == 0 ? k : 1 - k;
      const std::string tag = std::string("tp_") + names[which] + "_" + std::to_string(run++);
      ChildProcess reader_side({exe, "--child", "tp-read", "layer", std::to_string(domains[which]), tag}, true);
      const WriterStats w = throughput_write(Api::Layer, domains[which], tag, o.tp_seconds);
      std::istringstream out(reader_side.read_all_stdout());
      if (reader_side.wait(std::chrono::seconds(10)) != 0) throw std::runtime_error("throughput reader failed");
      unsigned long long received = 0, lost_n = 0;
      double secs = 0;
      if (!(out >> received >> secs >> lost_n) || secs <= 0) throw std::runtime_error("throughput reader: no result");
      recv_rate[which].push_back(static_cast<double>(received) / secs);
      lost[which] += lost_n;
      progress("[throughput round %d/%d] %-6s received %.0f samples/s (written %.0f/s, lost %llu)", round + 1,
               o.rounds, names[which], recv_rate[which].back(), static_cast<double>(w.written) / w.seconds, lost_n);
    }
  }
  std::printf("\n== dds_layer_bench --secure-domain: typed layer plain (domain %d) vs DDS Security (domain %d),"
              " %d rounds, 2 processes, loopback ==\n",
              o.domain, o.secure_domain, o.rounds);
  std::printf("round trip, reliable, waitset-driven, %d round trips per run (after %d warm-up)\n", o.count, o.warmup);
  std::printf("  %-11s %-6s %8s %9s %9s %9s %9s\n", "payload", "config", "samples", "p50 us", "p90 us", "p99 us",
              "mean us");
  for (Payload payload : payloads)
    for (int which = 0; which < 2; ++which) print_rtt_row(to_string(payload), names[which], rtt[{payload, which}]);
  std::printf("  ratio secure/plain:\n");
  for (Payload payload : payloads) {
    const auto& plain = rtt[{payload, 0}];
    const auto& secure = rtt[{payload, 1}];
    std::printf("  %-11s p50 %.3f  p90 %.3f  p99 %.3f  mean %.3f\n", to_string(payload),
                percentile(secure, 50) / percentile(plain, 50), percentile(secure, 90) / percentile(plain, 90),
                percentile(secure, 99) / percentile(plain, 99), mean(secure) / mean(plain));
  }
  const double plain_tp = median(recv_rate[0]), secure_tp = median(recv_rate[1]);
  std::printf("throughput, 1 KiB, reliable keep-last 256, %.1f s per run (median of %d runs)\n", o.tp_seconds,
              o.rounds);
  std::printf("  plain   received %10.0f samples/s  lost %llu\n", plain_tp, static_cast<unsigned long long>(lost[0]));
  std::printf("  secure  received %10.0f samples/s  lost %llu\n", secure_tp, static_cast<unsigned long long>(lost[1]));
  std::printf("  ratio secure/plain: %.3f\n", secure_tp / plain_tp);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--child") {
    try {
      return child_main(argc, argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "dds_layer_bench child: %s\n", e.what());
      return 1;
    }
  }
  try {
    const Options o = parse(argc, argv);
    if (!std::getenv("CYCLONEDDS_URI"))
      progress("note: CYCLONEDDS_URI is not set; Cyclone picks its default network interface");
    const std::string exe = self_exe();
    if (o.secure_domain >= 0) return secure_main(o, exe);
    const Payload payloads[] = {Payload::RobotState, Payload::Blob1K};

    // ---- round trips
    std::map<std::pair<Payload, Api>, std::vector<double>> rtt;
    int run = 0;
    for (int round = 0; round < o.rounds; ++round) {
      for (Payload payload : payloads) {
        const Api order[2] = {round % 2 == 0 ? Api::Raw : Api::Layer, round % 2 == 0 ? Api::Layer : Api::Raw};
        for (Api api : order) {
          const std::string tag = std::string(to_string(payload)) + "_" + to_string(api) + "_" + std::to_string(run++);
          ChildProcess echo_side({exe, "--child", "echo", to_string(api), to_string(payload),
                                  std::to_string(o.domain), tag},
                                 false);
          std::vector<double> v = ping(api, payload, o.domain, tag, o.warmup, o.count);
          if (echo_side.wait(std::chrono::seconds(10)) != 0) throw std::runtime_error("echo process failed");
          progress("[rtt round %d/%d] %-10s %-5s p50 %.1f us  p99 %.1f us", round + 1, o.rounds, to_string(payload),
                   to_string(api), percentile(v, 50), percentile(v, 99));
          auto& all = rtt[{payload, api}];
          all.insert(all.end(), v.begin(), v.end());
        }
      }
    }

    // ---- throughput
    std::map<Api, std::vector<double>> recv_rate, write_rate;
    std::map<Api, uint64_t> lost;
    for (int round = 0; round < o.rounds; ++round) {
      const Api order[2] = {round % 2 == 0 ? Api::Raw : Api::Layer, round % 2 == 0 ? Api::Layer : Api::Raw};
      for (Api api : order) {
        const std::string tag = std::string("tp_") + to_string(api) + "_" + std::to_string(run++);
        ChildProcess reader_side({exe, "--child", "tp-read", to_string(api), std::to_string(o.domain), tag}, true);
        const WriterStats w = throughput_write(api, o.domain, tag, o.tp_seconds);
        std::istringstream out(reader_side.read_all_stdout());
        if (reader_side.wait(std::chrono::seconds(10)) != 0) throw std::runtime_error("throughput reader failed");
        unsigned long long received = 0, lost_n = 0;
        double secs = 0;
        if (!(out >> received >> secs >> lost_n) || secs <= 0) throw std::runtime_error("throughput reader: no result");
        const double r = static_cast<double>(received) / secs;
        recv_rate[api].push_back(r);
        write_rate[api].push_back(static_cast<double>(w.written) / w.seconds);
        lost[api] += lost_n;
        progress("[throughput round %d/%d] %-5s received %.0f samples/s (written %.0f/s, lost %llu)", round + 1,
                 o.rounds, to_string(api), r, static_cast<double>(w.written) / w.seconds, lost_n);
      }
    }

    // ---- CPU cost of the API alone (one process, no network)
    std::map<std::pair<Payload, Api>, std::vector<double>> local;
    const int local_samples = o.count * 40;
    for (int round = 0; round < o.rounds; ++round) {
      for (Payload payload : payloads) {
        const Api order[2] = {round % 2 == 0 ? Api::Raw : Api::Layer, round % 2 == 0 ? Api::Layer : Api::Raw};
        for (Api api : order) {
          const std::string tag = std::string(to_string(payload)) + "_" + to_string(api) + "_" + std::to_string(run++);
          const double ns = local_cost_ns(api, payload, o.domain, tag, local_samples);
          local[{payload, api}].push_back(ns);
          progress("[in-process round %d/%d] %-10s %-5s %.0f ns per sample (write + take)", round + 1, o.rounds,
                   to_string(payload), to_string(api), ns);
        }
      }
    }

    // ---- report
    std::printf("\n== dds_layer_bench: typed layer vs raw Cyclone C API (%d rounds, 2 processes, loopback) ==\n",
                o.rounds);
    std::printf("round trip, reliable, waitset-driven, %d round trips per run (after %d warm-up)\n", o.count,
                o.warmup);
    std::printf("  %-11s %-6s %8s %9s %9s %9s %9s\n", "payload", "api", "samples", "p50 us", "p90 us", "p99 us",
                "mean us");
    for (Payload payload : payloads) {
      print_rtt_row(to_string(payload), "raw", rtt[{payload, Api::Raw}]);
      print_rtt_row(to_string(payload), "layer", rtt[{payload, Api::Layer}]);
    }
    std::printf("  ratio layer/raw:\n");
    for (Payload payload : payloads) {
      const auto& raw = rtt[{payload, Api::Raw}];
      const auto& layer = rtt[{payload, Api::Layer}];
      std::printf("  %-11s p50 %.3f  p90 %.3f  p99 %.3f  mean %.3f\n", to_string(payload),
                  percentile(layer, 50) / percentile(raw, 50), percentile(layer, 90) / percentile(raw, 90),
                  percentile(layer, 99) / percentile(raw, 99), mean(layer) / mean(raw));
    }
    const double raw_tp = median(recv_rate[Api::Raw]), layer_tp = median(recv_rate[Api::Layer]);
    std::printf("throughput, 1 KiB, reliable keep-last 256, %.1f s per run (median of %d runs)\n", o.tp_seconds,
                o.rounds);
    std::printf("  raw    received %10.0f samples/s (%.0f MiB/s)  written %10.0f/s  lost %llu\n", raw_tp,
                raw_tp * 1024 / 1048576, median(write_rate[Api::Raw]), static_cast<unsigned long long>(lost[Api::Raw]));
    std::printf("  layer  received %10.0f samples/s (%.0f MiB/s)  written %10.0f/s  lost %llu\n", layer_tp,
                layer_tp * 1024 / 1048576, median(write_rate[Api::Layer]),
                static_cast<unsigned long long>(lost[Api::Layer]));
    std::printf("  ratio layer/raw: %.3f (cost %+.1f %%)\n", layer_tp / raw_tp, (raw_tp / layer_tp - 1.0) * 100.0);
    std::printf("in-process write + take, one participant, no network (CPU cost of the API; median of %d runs"
                " of %d samples)\n",
                o.rounds, local_samples);
    for (Payload payload : payloads) {
      const double raw = median(local[{payload, Api::Raw}]), layer = median(local[{payload, Api::Layer}]);
      std::printf("  %-11s raw %7.0f ns  layer %7.0f ns  ratio %.3f (layer adds %.0f ns per sample)\n",
                  to_string(payload), raw, layer, layer / raw, layer - raw);
    }
    const double rs_cost = percentile(rtt[{Payload::RobotState, Api::Layer}], 50) /
                           percentile(rtt[{Payload::RobotState, Api::Raw}], 50);
    const double blob_cost =
        percentile(rtt[{Payload::Blob1K, Api::Layer}], 50) / percentile(rtt[{Payload::Blob1K, Api::Raw}], 50);
    std::printf("summary: layer cost over raw: RTT p50 %+.1f %% (RobotState), %+.1f %% (1 KiB); throughput %+.1f %%"
                " (goal: at most +20 %%)\n",
                (rs_cost - 1) * 100, (blob_cost - 1) * 100, (raw_tp / layer_tp - 1.0) * 100.0);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dds_layer_bench: %s\n", e.what());
    return 1;
  }
}
