#include "launch/domain_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

namespace gdnav::launch {

std::filesystem::path DomainLock::dir() {
    const char* env = std::getenv("GDNAV_DOMAIN_LOCKS");
    return env && *env ? std::filesystem::path(env) : std::filesystem::path("/tmp/gdnav-domains");
}

DomainLock::~DomainLock() { release(); }

void DomainLock::release() {
    if (fd_ >= 0) close(fd_);  // closing the only descriptor releases the flock
    fd_ = -1;
}

bool DomainLock::try_lock(int domain) {
    release();
    const auto d = dir();
    std::error_code ec;
    if (std::filesystem::create_directories(d, ec))
        chmod(d.c_str(), 01777);  // every user's runs share the folder (sticky, like /tmp)
    const std::string file = (d / (std::to_string(domain) + ".lock")).string();
    // Read-only, mode 0666: another user's run can lock the file too (flock needs no write access).
    const int fd = open(file.c_str(), O_RDONLY | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) return false;
    (void)fchmod(fd, 0666);  // past the umask; fails harmlessly on a file of another user
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        close(fd);
        return false;
    }
    fd_ = fd;
    return true;
}

int DomainLock::lock_free_domain() {
    for (int d = kFirstAutoDomain; d <= kLastDomain; ++d)
        if (try_lock(d)) return d;
    throw std::runtime_error("no free DDS domain on this host: every one from " + std::to_string(kFirstAutoDomain) +
                             " to " + std::to_string(kLastDomain) + " is held by a run (locks in " + dir().string() +
                             "); give --domain");
}

void choose_domain(framework::RunConfig& rc, DomainLock& lock) {
    if (rc.domain_given) {
        (void)lock.try_lock(rc.domain_id);
        return;
    }
    rc.domain_id = lock.lock_free_domain();
    framework::RunOverrides o;
    o.domain_id = rc.domain_id;
    const std::string faults_origin = rc.faults_origin;  // errors keep naming the file the faults came from
    rc = framework::RunConfig::parse(rc.to_yaml(), rc.origin, o);
    rc.faults_origin = faults_origin;
    spdlog::info("DDS domain {} (no other run of this host uses it; --domain chooses one)", rc.domain_id);
}

}  // namespace gdnav::launch
