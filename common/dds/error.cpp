#include "common/dds/error.hpp"

namespace autonomy::dds {

namespace {
// A refusal by DDS Security names where the grants come from, so that an operator knows which
// file to change rather than suspecting the network.
std::string explain(dds_return_t code) {
  if (code == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY)
    return " (DDS Security: this process's identity is not granted it; grants come from "
           "deploy/security/access.table, docs/security.md)";
  return "";
}
}  // namespace

DdsError::DdsError(const std::string& what, dds_return_t code)
    : std::runtime_error(what + ": " + dds_strretcode(code) + explain(code)), code_(code) {}

dds_return_t check(dds_return_t rc, const char* what) {
  if (rc < 0) throw DdsError(what, rc);
  return rc;
}

dds_return_t check(dds_return_t rc, const std::string& what) { return check(rc, what.c_str()); }

}  // namespace autonomy::dds
