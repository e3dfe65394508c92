#pragma once
// A domain participant: the process's presence on one DDS domain.
#include "common/dds/entity.hpp"

#include <string>

namespace autonomy::dds {

class Participant {
 public:
  // Throws DdsError when the domain cannot be joined (bad domain id, CYCLONEDDS_URI errors,
  // MaxAutoParticipantIndex reached).
  explicit Participant(dds_domainid_t domain);

  dds_entity_t handle() const { return entity_.handle(); }
  dds_domainid_t domain() const { return domain_; }

 private:
  dds_domainid_t domain_;
  Entity entity_;
};

}  // namespace autonomy::dds
