#pragma once
// The floor as the courier's executive needs it: where each place is, which room it is in, and
// which door leads into that room. Built by the node from the courier's office knowledge; plain
// data, no behaviour.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace autonomy::courier {

struct FloorPlace {
  double x = 0.0;
  double y = 0.0;
  std::string room;     // "" for the hallway and places in no room
  double radius = 1.0;  // a robot within this distance is at the place
  std::string person;   // who hands over here ("" for stations and places nobody works at)
};

struct Floor {
  std::map<std::string, FloorPlace> places;
  std::map<std::string, std::string> door_of_room;  // room -> the door a robot enters it by
  std::set<std::string> doors;  // every door of the map; sightings of other ids are ignored
  // Where a robot waits in sight of a door, beside it on the hallway side (out of the doorway):
  // a robot holding the object of a job behind a closed door and with nothing else to do waits
  // there, so that it sees the door open. Doors without one: the robot waits where it is.
  struct Lookout {
    double x = 0.0;
    double y = 0.0;
  };
  std::map<std::string, Lookout> door_lookouts;
  // Where an idle robot of a fleet waits out of everybody's way (Scenario.parking), one robot
  // per spot. None: it goes back to where it joined the fleet.
  struct ParkingSpot {
    std::string name;
    double x = 0.0;
    double y = 0.0;
  };
  std::vector<ParkingSpot> parking;
  // The floor area of each room that has a door (Scenario.rooms' bounds). A robot of a fleet
  // inside one holds the room: another robot whose next stop is in it waits outside until it has
  // left (room_claims.cpp). A room without an area is held only by robots bound for it.
  struct Area {
    double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;
    bool contains(double x, double y) const { return x >= min_x && x <= max_x && y >= min_y && y <= max_y; }
  };
  std::map<std::string, Area> room_areas;

  const FloorPlace* place(const std::string& name) const {
    const auto it = places.find(name);
    return it == places.end() ? nullptr : &it->second;
  }
  // The door into the room of `place`, if it has one.
  std::optional<std::string> door_to(const std::string& place) const {
    const FloorPlace* p = this->place(place);
    if (!p || p->room.empty()) return std::nullopt;
    const auto it = door_of_room.find(p->room);
    if (it == door_of_room.end()) return std::nullopt;
    return it->second;
  }
};

}  // namespace autonomy::courier
