#pragma once
// Checks a run's DDS Security material before anything starts (docs/deployment.md, "Security"): the process that
// starts a run, a host's slice of a plan or an operator tool calls it for every identity it will use, so that a bad
// directory is one line naming the file and the problem. It needs OpenSSL, so it lives here, in the launch layer,
// and not in the dds layer that the client library links: an external member's process with bad material gets Fast
// DDS's own refusal to create its participant instead (docs/external.md).
#include <filesystem>
#include <string>

namespace gdnav::launch::pki {

// Checks that DIR holds a usable identity: the CA, the identity's certificate signed by it and valid now, the key
// matching the certificate, governance and permissions documents signed by the CA, and a grant for the identity.
// Throws config::ConfigError with one line naming the file and the problem.
void check_identity(const std::filesystem::path& dir, const std::string& identity);

}  // namespace gdnav::launch::pki
