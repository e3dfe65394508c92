#pragma once
// Every failing Cyclone call becomes a DdsError carrying the call, the DDS error text and code.
#include <dds/dds.h>

#include <stdexcept>
#include <string>

namespace autonomy::dds {

class DdsError : public std::runtime_error {
 public:
  DdsError(const std::string& what, dds_return_t code);
  dds_return_t code() const { return code_; }

 private:
  dds_return_t code_;
};

// Returns rc when it is not an error (entity handles and counts are positive), throws otherwise.
dds_return_t check(dds_return_t rc, const char* what);
dds_return_t check(dds_return_t rc, const std::string& what);

}  // namespace autonomy::dds
