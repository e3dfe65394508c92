#!/usr/bin/env python3
"""Writes deploy/scenarios/recon.pbtxt and recon/recon.{yaml,pgm}: the reconnaissance area of the
robot-teams paper (internalized-plans-robot-teams.txt, section 4): 250 x 250 m at 1 m, a
250 x 50 m open area along the bottom edge where the robots start, blocks of buildings with
alleys between them, a ~25 m wide street up the middle towards a goal ~250 m from the start
line, parked cars along the street (in the 1 m occupancy map), communication-attenuating areas
(alleys, parked cars) and dispersion waypoints. Deterministic: no randomness.
"""
import os

HERE = os.path.dirname(__file__)
OUT = os.path.join(HERE, "..", "recon.pbtxt")
MAP_DIR = os.path.join(HERE, "..", "recon")
N = 250                          # m and cells
STREET = (112.5, 137.5)          # x range of the street
OPEN_TOP = 50.0                  # the open area is y in [0, 50]
BLOCK_Y = [(60, 95), (101, 136), (142, 177), (183, 218), (224, 240)]   # 6 m alleys between
LEFT_X = [(8, 38), (44, 74), (80, 106)]                                # 6 m alleys between
RIGHT_X = [(144, 170), (176, 206), (212, 242)]


def f(v):
    return f"{v:g}"


def attenuating_areas():
    """The alleys and the parked cars: [(name, (x0, y0, x1, y1), dB/m, entry dB)]. The mission
    generator (deploy/missions/generators/recon_missions.py) uses the same rectangles."""
    areas = []
    for side, xs in (("west", LEFT_X), ("east", RIGHT_X)):
        for i in range(len(xs) - 1):   # north-south alleys between blocks
            areas.append((f"alley-{side}-ns-{i}", (xs[i][1], BLOCK_Y[0][0], xs[i + 1][0], BLOCK_Y[-1][1]), 1.5, 6.0))
        for j in range(len(BLOCK_Y) - 1):   # east-west alleys
            areas.append((f"alley-{side}-ew-{j}", (xs[0][0], BLOCK_Y[j][1], xs[-1][1], BLOCK_Y[j + 1][0]), 1.5, 6.0))
    areas.append(("parked-cars-west", (STREET[0], 60, STREET[0] + 3, 240), 2.0, 3.0))
    areas.append(("parked-cars-east", (STREET[1] - 3, 60, STREET[1], 240), 2.0, 3.0))
    return areas


def main():
    buildings = []  # (name, vertices)
    for side, xs in (("west", LEFT_X), ("east", RIGHT_X)):
        for j, (y0, y1) in enumerate(BLOCK_Y):
            for i, (x0, x1) in enumerate(xs):
                name = f"{side}-{j}-{i}"
                if (i + j) % 3 == 1:
                    # An L-shaped building: the north corner away from the street cut out. The yard
                    # opens towards the goal, so it is no box canyon for a robot heading north
                    # (a yard opening south traps a purely reactive robot for good).
                    cut_x = x0 + (x1 - x0) * 0.5
                    cut_y = y0 + (y1 - y0) * 0.5
                    if side == "west":
                        v = [(x0, y0), (x1, y0), (x1, y1), (cut_x, y1), (cut_x, cut_y), (x0, cut_y)]
                    else:
                        v = [(x0, y0), (x1, y0), (x1, cut_y), (cut_x, cut_y), (cut_x, y1), (x0, y1)]
                else:
                    v = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
                buildings.append((name, v))

    # Parked cars (2 x 5 m) along both kerbs of the street, with gaps; they go into the raster.
    cars = []
    for k, y in enumerate(range(62, 236, 9)):
        if k % 4 != 3:
            cars.append((STREET[0] + 0.5, y, STREET[0] + 2.5, y + 5))
        if k % 5 != 2:
            cars.append((STREET[1] - 2.5, y + 3, STREET[1] - 0.5, y + 8))
    # A few abandoned cars in the open area.
    cars += [(60, 20, 65, 22), (170, 28, 172, 33), (95, 40, 100, 42)]

    os.makedirs(MAP_DIR, exist_ok=True)
    pixels = bytearray([254] * (N * N))  # free
    for (x0, y0, x1, y1) in cars:
        for y in range(int(y0), int(-(-y1 // 1))):
            for x in range(int(x0), int(-(-x1 // 1))):
                pixels[(N - 1 - y) * N + x] = 0  # image row 0 is the top (y = 249)
    with open(os.path.join(MAP_DIR, "recon.pgm"), "wb") as fh:
        fh.write(b"P5\n# recon area: parked cars, 1 m per pixel (deploy/scenarios/generators/recon.py)\n")
        fh.write(f"{N} {N}\n255\n".encode())
        fh.write(bytes(pixels))
    with open(os.path.join(MAP_DIR, "recon.yaml"), "w") as fh:
        fh.write("# Parked cars of the reconnaissance area (ROS map_server format).\n"
                 "image: recon.pgm\nresolution: 1.0\norigin: [0.0, 0.0, 0.0]\n"
                 "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n")

    areas = attenuating_areas()

    out = ["""# The reconnaissance area of the robot-teams paper (internalized-plans-robot-teams.txt,
# section 4): 250 x 250 m at 1 m. Robots start along the bottom edge in a 250 x 50 m open area,
# disperse to waypoints, regroup at the street entrance and follow the ~25 m wide street up the
# middle to the goal about 250 m from the start line. Buildings (polygons) stand in blocks with
# 6 m alleys between them; parked cars line the street (occupancy map recon/recon.yaml, 1 m
# cells). Alleys and the parked cars attenuate radio signals (attenuating_areas); buildings cost
# the radio model's wall and inside losses.
#
# Generated by deploy/scenarios/generators/recon.py.
# Schema: autonomy.config.Scenario in idl/scenario.proto. Units: metres, seconds, radians.
#
#   y=250 +------------------ goal (125, 245) -----------------+
#         | [bldg][bldg][bldg] |  street  | [bldg][bldg][bldg]  |
#         |   alleys ...       | 25 m     |   alleys ...        |
#   y=60  | [bldg][bldg][bldg] |  cars    | [bldg][bldg][bldg]  |
#   y=50  +-------------- street entrance (125, 55) ------------+
#         |  w-west            w-centre              w-east     |   open area 250 x 50
#   y=0   +---- start line: robots along the bottom edge -------+
""", 'name: "recon"\n', "world {", f"  width: {N}\n  height: {N}"]
    for name, v in buildings:
        pts = " ".join(f"vertices {{ x: {f(x)} y: {f(y)} }}" for x, y in v)
        out.append(f'  polygons {{ name: "{name}" {pts} }}')
    out.append('  maps { yaml: "recon/recon.yaml" }  # parked cars')
    out.append("}\n")
    for name, (x0, y0, x1, y1), db_m, entry in areas:
        out.append(f'attenuating_areas {{ name: "{name}" loss_db_per_m: {f(db_m)} entry_loss_db: {f(entry)}\n'
                   f"  vertices {{ x: {f(x0)} y: {f(y0)} }} vertices {{ x: {f(x1)} y: {f(y0)} }}"
                   f" vertices {{ x: {f(x1)} y: {f(y1)} }} vertices {{ x: {f(x0)} y: {f(y1)} }} }}")
    out.append("""
# Outdoor 2.4 GHz radios (radio_parameters.hpp defaults: 20 dBm, log-distance n = 3, -90 dBm).
radio { wall_loss_db: 12 inside_loss_db_per_m: 0.5 }

# Dispersion waypoints in the open area, the regrouping checkpoint and the goal.
waypoints { name: "w-west" position { x: 40 y: 30 } }
waypoints { name: "w-centre" position { x: 125 y: 30 } }
waypoints { name: "w-east" position { x: 210 y: 30 } }
waypoints { name: "street-entrance" position { x: 125 y: 55 } }
waypoints { name: "goal" position { x: 125 y: 245 } }
""")
    for k, x in enumerate((100, 125, 150)):
        out.append(f"""robots {{
  id: "scout{k + 1}"
  kind: "scout"
  kinematics: HOLONOMIC
  start {{ x: {x} y: 3 theta: 1.5708 }}
  spawn_at_start: true
}}""")
    out.append("""
attach_defaults {
  kinematics: HOLONOMIC
  radius: 0.4
  max_speed: 2.0
  max_omega: 2.0
  kind: "scout"
  capacity: 0
  sensors {
    range { rays: 32 max_range_m: 20.0 noise_stddev_m: 0.05 }
    pose { position_noise_m: 0.5 heading_noise_rad: 0.02 }
  }
}

simulation {
  mode: LOCKSTEP
  step_s: 0.1
  seed: 11
}
""")
    with open(OUT, "w") as fh:
        fh.write("\n".join(out))


if __name__ == "__main__":
    main()
