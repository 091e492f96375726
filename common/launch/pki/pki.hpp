#pragma once
// `gdnav pki init`: makes a security directory (layout in security.hpp) with the OpenSSL command-line tool: an
// ECDSA P-256 CA, one certificate and key per identity, and the governance and permissions documents signed by the
// CA. Each identity may publish only the topics listed for it; every identity may subscribe to every topic.
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::launch::pki {

struct Identity {
    std::string name;
    std::vector<std::string> publish;  // DDS topic names it may write
};

struct PkiOptions {
    int days{365};             // certificate and grant validity from now
    std::string openssl{"openssl"};
};

// The domain rules: authenticated participants only, discovery, liveliness, metadata and data encrypted (AES-GCM),
// read and write access control on every topic.
std::string governance_xml();
// One grant per identity: publish its topics, subscribe to all, everything else denied. Times are UTC ISO 8601.
std::string permissions_xml(const std::vector<Identity>& ids, const std::string& not_before,
                            const std::string& not_after);

// Writes the directory (created; existing CA reused only if absent -> a fresh CA is made, never overwritten: throws
// if DIR/ca.pem exists). Throws std::runtime_error naming the failing openssl command.
void init_pki(const std::filesystem::path& dir, const std::vector<Identity>& ids, const PkiOptions& opt);

// Runs the openssl tool with these arguments; throws std::runtime_error with its stderr when it fails.
void run_openssl(const std::string& openssl, const std::vector<std::string>& args, const std::filesystem::path& log);

}  // namespace gdnav::launch::pki
