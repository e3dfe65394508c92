#include "common/dds/participant.hpp"

#include "common/dds/error.hpp"

namespace autonomy::dds {

Participant::Participant(dds_domainid_t domain)
    : domain_(domain),
      entity_(check(dds_create_participant(domain, nullptr, nullptr), "dds_create_participant")) {}

}  // namespace autonomy::dds
