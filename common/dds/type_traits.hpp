#pragma once
// The bridge between a C++ value type and its idlc-generated C type. Each value type has one
// DdsType specialisation (see conversions/*.cpp) naming the C type, its descriptor and the two
// conversions. Only common/dds and DDS nodes see the C types.
#include <dds/dds.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace autonomy::dds {

template <typename T>
struct DdsType;  // specialised per message type

// Keeps buffers alive while one converted sample is written. dds_write copies the sample before
// it returns, so a C sample may point into the value it came from and into an Arena.
class Arena {
 public:
  template <typename U>
  U* allocate(std::size_t n) {
    auto block = std::make_unique<U[]>(n);
    U* raw = block.get();
    blocks_.push_back(std::shared_ptr<void>(block.release(), [](void* p) { delete[] static_cast<U*>(p); }));
    return raw;
  }

 private:
  std::vector<std::shared_ptr<void>> blocks_;
};

// A C string view of a std::string for writing; the sample never outlives the string.
inline char* c_str(const std::string& s) { return const_cast<char*>(s.c_str()); }
inline std::string from_c_str(const char* s) { return s ? std::string(s) : std::string(); }

}  // namespace autonomy::dds
