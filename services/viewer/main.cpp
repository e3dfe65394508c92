// The viewer process: a live view of the world in a browser. A DDS participant like any other
// service (start it in a set or beside a running one, on the same --domain); it serves one page
// and a WebSocket on --port and pushes the world's state to every page (docs/viewer.md).
#include "services/viewer/dds/viewer_node.hpp"

#include <memory>

using namespace autonomy;

int main(int argc, char** argv) {
  viewer::ViewerNodeOptions options;
  return service::run_service(
      argc, argv, "viewer", "Viewer: the live world in a web browser (map, robots, doors, goals, courier jobs)",
      service::InstanceFlag::Instance,
      [&](CLI::App& app) {
        app.footer("Open http://127.0.0.1:PORT/ in a browser on this host; from another host, tunnel the port: "
                   "ssh -L PORT:127.0.0.1:PORT HOST. Foxglove-compatible viewers connect to ws://127.0.0.1:PORT/ "
                   "(subprotocol foxglove.websocket.v1: every catalogue topic, CDR with its IDL) (docs/viewer.md).");
        app.add_option("--port", options.web.port, "TCP port of the page and its WebSocket (0: any free port)")
            ->check(CLI::Range(0, 65535))
            ->capture_default_str();
        app.add_option("--bind", options.web.bind_address,
                       "Address to listen on (127.0.0.1: this host only; 0.0.0.0: every interface)")
            ->capture_default_str();
        app.add_option("--rate", options.rate_hz, "Frames pushed to the pages per second at most")
            ->check(CLI::Range(0.1, 100.0))
            ->capture_default_str();
        app.add_option("--trail", options.limits.trail_points, "Positions kept per robot for its drawn tail")
            ->check(CLI::Range(0, 10000))
            ->capture_default_str();
      },
      [&](service::Service& service) { return std::make_unique<viewer::ViewerNode>(service, options); });
}
