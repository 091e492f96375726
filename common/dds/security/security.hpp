#pragma once
// DDS Security for a run (docs/deployment.md, "Security"): Fast DDS's built-in plugins, PKI-DH authentication,
// Access-Permissions access control and AES-GCM-GMAC crypto, configured from a directory made by `gdnav pki init`:
//
//   DIR/ca.pem, DIR/ca.key              the run's certificate authority (identity and permissions CA)
//   DIR/governance.xml, governance.p7s  the domain rules, signed by the CA (S/MIME)
//   DIR/permissions.xml, permissions.p7s  one grant per identity, signed by the CA
//   DIR/identities/NAME.pem, NAME.key   one certificate (subject /CN=NAME/O=gdnav) and key per identity
//
// An identity is a process's DDS participant: `clock`, a member hosted alone (its member name), `composed` (the
// process hosting several members) or `operator` (gdnav fault and monitoring tools).
#include <filesystem>
#include <string>
#include <vector>

#include "dds/compat.hpp"

namespace eprosima::fastdds::dds {
class DomainParticipantQos;
}

namespace gdnav::dds::security {

inline constexpr const char* kClockIdentity = "clock";
inline constexpr const char* kComposedIdentity = "composed";
inline constexpr const char* kOperatorIdentity = "operator";
inline constexpr const char* kOrganisation = "gdnav";

// The identity of a process hosting these members: the member's name when alone, else `composed`.
std::string process_identity(const std::vector<std::string>& members);
// "O=gdnav,CN=NAME": the RFC 2253 form of the certificate subject /CN=NAME/O=gdnav, as a permissions grant names it.
std::string subject_name(const std::string& identity);

// The check of the material itself (certificates, keys, signed documents) is OpenSSL's and the launch layer's
// (launch/pki/identity_check.hpp): the dds layer, which the client library links, does not need OpenSSL.

// Sets the participant properties that turn the built-in security plugins on for `identity`.
void apply(eprosima::fastdds::dds::DomainParticipantQos& qos, const std::filesystem::path& dir,
           const std::string& identity);

}  // namespace gdnav::dds::security
