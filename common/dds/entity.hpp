#pragma once
// Sole owner of one Cyclone entity handle. Deleting a participant deletes its children too, so
// children may outlive nothing but their participant; members are declared in creation order
// and destroyed in reverse, which keeps that rule by construction.
#include <dds/dds.h>

#include <utility>

namespace autonomy::dds {

class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  Entity(Entity&& o) noexcept : handle_(std::exchange(o.handle_, 0)) {}
  Entity& operator=(Entity&& o) noexcept {
    if (this != &o) {
      reset();
      handle_ = std::exchange(o.handle_, 0);
    }
    return *this;
  }
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;
  ~Entity() { reset(); }

  dds_entity_t handle() const { return handle_; }
  explicit operator bool() const { return handle_ > 0; }

  // Never throws: a handle already deleted with its parent answers "bad parameter", harmlessly.
  void reset() noexcept {
    if (handle_ > 0) (void)dds_delete(handle_);
    handle_ = 0;
  }

 private:
  dds_entity_t handle_ = 0;
};

}  // namespace autonomy::dds
