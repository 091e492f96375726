#pragma once
// DDS domains of the runs on this host: a run holds an flock on <dir>/<domain>.lock (dir: /tmp/gdnav-domains) for
// its lifetime, so a run without --domain takes one that no other run of this host uses. The lock ends with the
// process (even when it is killed); nothing is left to clean up but empty files.
#include <filesystem>

#include "framework/run_config.hpp"

namespace gdnav::launch {

class DomainLock {
public:
    DomainLock() = default;
    ~DomainLock();
    DomainLock(const DomainLock&) = delete;
    DomainLock& operator=(const DomainLock&) = delete;

    // Takes the lock of `domain` unless another process holds it (then false). Releases a lock held before.
    bool try_lock(int domain);
    // The lowest domain from kFirstAutoDomain up that no run of this host holds, locked; throws when all are held.
    int lock_free_domain();
    void release();

    // Auto-picked domains start here (below the ones gdnav's tests name) and end at Fast DDS's highest domain id
    // for the default UDP port mapping.
    static constexpr int kFirstAutoDomain = 20;
    static constexpr int kLastDomain = 232;
    // The folder of the lock files ($GDNAV_DOMAIN_LOCKS, else /tmp/gdnav-domains).
    static std::filesystem::path dir();

private:
    int fd_{-1};
};

// A run without a given domain takes the lowest one that no run of this host holds, and says so; a given domain is
// locked too when it is free, so that runs without --domain keep off it.
void choose_domain(framework::RunConfig& rc, DomainLock& lock);

}  // namespace gdnav::launch
