#include "common/dds/participant.hpp"

#include "common/dds/error.hpp"

#include <cstdlib>
#include <string>

namespace autonomy::dds {

namespace {
// Cyclone prints why DDS Security refused the participant (a bad signature, an expired or
// foreign certificate) on its own line; the exception says where to look and how to check.
std::string create_what() {
  const char* uri = std::getenv("CYCLONEDDS_URI");
  const std::string u = uri ? uri : "";
  if (u.find("Security") == std::string::npos && u.find("/identities/") == std::string::npos)
    return "dds_create_participant";
  return "dds_create_participant with DDS Security (" + u +
         "): Cyclone's reason is on the line above; deploy/security/security.sh check DIR NAME names the "
         "faulty file";
}
}  // namespace

Participant::Participant(dds_domainid_t domain)
    : domain_(domain), entity_([&] {
        const dds_entity_t e = dds_create_participant(domain, nullptr, nullptr);
        return e < 0 ? check(e, create_what()) : e;
      }()) {}

}  // namespace autonomy::dds
