#include "dds/security/security.hpp"

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>

namespace gdnav::dds::security {

namespace fs = std::filesystem;

namespace {

std::string file_uri(const fs::path& p) { return "file://" + fs::absolute(p).lexically_normal().string(); }

}  // namespace

std::string process_identity(const std::vector<std::string>& members) {
    return members.size() == 1 ? members.front() : std::string(kComposedIdentity);
}

std::string subject_name(const std::string& identity) {
    // RFC 2253 form of the certificate subject /CN=NAME/O=gdnav (last RDN first): Fast DDS 2.9 matches a grant's
    // subject_name against that string, so "CN=NAME,O=gdnav" would never match (measured).
    return std::string("O=") + kOrganisation + ",CN=" + identity;
}

void apply(eprosima::fastdds::dds::DomainParticipantQos& qos, const fs::path& dir, const std::string& identity) {
    auto& p = qos.properties().properties();
    const auto set = [&p](const std::string& k, const std::string& v) { p.emplace_back(k, v); };
    set("dds.sec.auth.plugin", "builtin.PKI-DH");
    set("dds.sec.auth.builtin.PKI-DH.identity_ca", file_uri(dir / "ca.pem"));
    set("dds.sec.auth.builtin.PKI-DH.identity_certificate", file_uri(dir / "identities" / (identity + ".pem")));
    set("dds.sec.auth.builtin.PKI-DH.private_key", file_uri(dir / "identities" / (identity + ".key")));
    set("dds.sec.access.plugin", "builtin.Access-Permissions");
    set("dds.sec.access.builtin.Access-Permissions.permissions_ca", file_uri(dir / "ca.pem"));
    set("dds.sec.access.builtin.Access-Permissions.governance", file_uri(dir / "governance.p7s"));
    set("dds.sec.access.builtin.Access-Permissions.permissions", file_uri(dir / "permissions.p7s"));
    set("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
}

}  // namespace gdnav::dds::security
