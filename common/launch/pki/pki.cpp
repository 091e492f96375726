#include "launch/pki/pki.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dds/security/security.hpp"

extern char** environ;

namespace gdnav::launch::pki {

namespace fs = std::filesystem;

namespace {

std::string utc_iso(std::time_t t) {
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
    return buf;
}

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream f(file);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

void run_openssl(const std::string& openssl, const std::vector<std::string>& args, const fs::path& log) {
    std::vector<std::string> all{openssl};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, openssl.c_str(), &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    std::string cmd;
    for (const auto& a : all) cmd += (cmd.empty() ? "" : " ") + a;
    if (rc != 0) throw std::runtime_error("cannot run '" + openssl + "' (install the openssl package)");
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::ifstream f(log);
        std::stringstream ss;
        ss << f.rdbuf();
        std::string err = ss.str();
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        throw std::runtime_error("'" + cmd + "' failed: " + err.substr(0, 400));
    }
}

std::string governance_xml() {
    return R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- gdnav governance (gdnav pki init): only authenticated participants join; discovery, liveliness, RTPS messages,
     metadata and data are protected with AES-GCM; every topic has read and write access control. -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-Security/20170801/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>0</min><max>232</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>ENCRYPT</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
)";
}

std::string permissions_xml(const std::vector<Identity>& ids, const std::string& not_before,
                            const std::string& not_after) {
    std::ostringstream x;
    x << R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- gdnav permissions (gdnav pki init): each identity publishes only its own topics and reads every topic. -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-Security/20170801/omg_shared_ca_permissions.xsd">
  <permissions>
)";
    for (const auto& id : ids) {
        x << "    <grant name=\"" << id.name << "\">\n"
          << "      <subject_name>" << dds::security::subject_name(id.name) << "</subject_name>\n"
          << "      <validity><not_before>" << not_before << "</not_before><not_after>" << not_after
          << "</not_after></validity>\n"
          << "      <allow_rule>\n"
          << "        <domains><id_range><min>0</min><max>232</max></id_range></domains>\n";
        if (!id.publish.empty()) {
            x << "        <publish><topics>\n";
            for (const auto& t : id.publish) x << "          <topic>" << t << "</topic>\n";
            x << "        </topics></publish>\n";
        }
        x << "        <subscribe><topics><topic>*</topic></topics></subscribe>\n"
          << "      </allow_rule>\n"
          << "      <default>DENY</default>\n"
          << "    </grant>\n";
    }
    x << "  </permissions>\n</dds>\n";
    return x.str();
}

void init_pki(const fs::path& dir, const std::vector<Identity>& ids, const PkiOptions& opt) {
    if (fs::exists(dir / "ca.pem"))
        throw std::runtime_error(dir.string() + " already holds a CA (ca.pem): choose a new directory");
    fs::create_directories(dir / "identities");
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace);
    const fs::path log = dir / "openssl.log";
    const std::string days = std::to_string(opt.days);
    const auto ssl = [&](const std::vector<std::string>& a) { run_openssl(opt.openssl, a, log); };
    const std::string ca_key = (dir / "ca.key").string(), ca_pem = (dir / "ca.pem").string();
    ssl({"genpkey", "-algorithm", "EC", "-pkeyopt", "ec_paramgen_curve:P-256", "-out", ca_key});
    ssl({"req", "-x509", "-new", "-key", ca_key, "-sha256", "-days", days, "-subj",
         std::string("/CN=gdnav CA/O=") + dds::security::kOrganisation, "-out", ca_pem});
    for (const auto& id : ids) {
        const fs::path base = dir / "identities" / id.name;
        const std::string key = base.string() + ".key", csr = base.string() + ".csr", pem = base.string() + ".pem";
        ssl({"genpkey", "-algorithm", "EC", "-pkeyopt", "ec_paramgen_curve:P-256", "-out", key});
        ssl({"req", "-new", "-key", key, "-subj", "/CN=" + id.name + "/O=" + dds::security::kOrganisation, "-out",
             csr});
        ssl({"x509", "-req", "-in", csr, "-CA", ca_pem, "-CAkey", ca_key, "-CAcreateserial", "-sha256", "-days",
             days, "-out", pem});
        fs::remove(csr);
    }
    const std::time_t now = std::time(nullptr);
    write_text(dir / "governance.xml", governance_xml());
    write_text(dir / "permissions.xml",
               permissions_xml(ids, utc_iso(now - 3600), utc_iso(now + static_cast<std::time_t>(opt.days) * 86400)));
    for (const char* doc : {"governance", "permissions"})
        ssl({"smime", "-sign", "-in", (dir / (std::string(doc) + ".xml")).string(), "-text", "-out",
             (dir / (std::string(doc) + ".p7s")).string(), "-signer", ca_pem, "-inkey", ca_key});
    fs::remove(log);
    fs::remove(dir / "ca.srl");
}

}  // namespace gdnav::launch::pki
