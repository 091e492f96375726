#pragma once
// The clock's state (internal: Clock's implementation, split by concern):
//   clock.cpp                  the main loop: gathering, the start, Ticks, the end of the run
//   clock/clock_members.cpp    members: their heartbeats, StepDone, liveness, death, rejoin
//   clock/clock_faults.cpp     faults requested while the run flies (gdnav fault), faults.yaml
//   clock/clock_report.cpp     progress lines, clock_summary.yaml, the run's end
#include "dds/clock/clock.hpp"

#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <fastdds/dds/core/condition/WaitSet.hpp>
#include <spdlog/spdlog.h>

#include "dds/compat.hpp"
#include "dds/dds_context.hpp"
#include "dds/foreign_runs.hpp"
#include "dds/socket_buffers.hpp"
#include "framework/lockstep.hpp"
#include "msgs/messages.hpp"
#include "dds/security/security.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;


struct Clock::Impl {
    struct Member {
        std::string name;
        std::string host;
        std::string inputs;
        std::string outputs;
        bool expected{false};
        bool free{false};
        bool present{false};
        bool ready{false};
        bool dead{false};
        std::uint64_t done_count{0};  // steps 0 .. done_count-1 reported done (members step in order)
        double last_seen_s{0.0};
        std::uint64_t dead_at_step{0};
        std::string dead_reason;
        std::uint32_t faults_version{0};  // fault schedule the member has adopted
        std::string rejected;  // its latest heartbeat's count of rejected samples ("TOPIC:N:M,...", host_inbox.hpp)
        std::uint64_t beat_step{0};  // the last completed step its latest heartbeat of this run named
        bool beat_heard{false};
        // Not in the barrier and writes nothing (e.g. the live bridge): it cannot change the run's outputs.
        [[nodiscard]] bool observer() const { return free && outputs.empty(); }
    };

    const framework::RunConfig& rc;
    ClockOptions opt;
    std::unique_ptr<DdsContext> dds;
    DataWriter* tick_writer{nullptr};
    DataWriter* control_writer{nullptr};
    DataWriter* status_writer{nullptr};
    DataReader* done_reader{nullptr};
    DataReader* status_reader{nullptr};
    DataReader* fault_reader{nullptr};
    WaitSet waitset;

    std::map<std::string, Member> members;
    std::vector<Member*> table;  // index = member index
    // Claim: the clock listens for another clock on its domain (docs/protocol.md, "Run token") before anything else.
    enum class Phase { Claim, Gather, Configured, Running } phase{Phase::Claim};
    std::uint64_t current{0};
    std::uint64_t dead_mask{0};
    double start_s{0.0}, run_start_s{0.0}, last_progress_s{0.0}, next_log_s{0.0}, next_hb_s{0.0};
    double last_tick_sent_s{0.0};
    double configured_s{0.0};   // when the member table was sent (matching timeout counts from here)
    double next_wait_log_s{0.0};
    std::set<std::string> refused;  // members refused for a protocol version mismatch (logged once)
    bool tick_pending{false};
    std::string host_id{framework::host_identity()};
    const std::uint64_t token{draw_run_token()};  // the run's token (on the wire only)
    ForeignRuns foreign;                          // control messages of other runs (other tokens), ignored
    std::string rival;                            // another clock heard while claiming the domain
    double other_life_s{0.0};                     // while claiming: when the domain last showed other life
    std::uint64_t participants_seen{0};           // while claiming: discovery generation last looked at
    // The fault schedule: the run config's, grown by faults injected live (gdnav fault). Members acknowledge each
    // version (ComponentStatus.faults_version) before the clock lets the run reach the step a new fault acts at.
    framework::faults::FaultSchedule schedule{rc.faults};
    std::uint32_t faults_version{0};
    bool adopting{false};
    std::vector<std::string> rejoined;  // members that came back after being declared dead
    double adopt_start_s{0.0};

    msg::Tick tick;
    msg::StepDone done_in;
    msg::ComponentStatus status_in, status_out;
    msg::RunControl control;
    msg::FaultRequest fault_in;

    Impl(const framework::RunConfig& r, ClockOptions o) : rc(r), opt(std::move(o)) {
        if (opt.members.empty()) opt.members = rc.member_names();
        for (const auto& n : opt.members) {
            Member m;
            m.name = n;
            m.expected = true;
            members[n] = m;
        }
        dds = std::make_unique<DdsContext>(rc.domain_id, rc.dds_profile, "gdnav.clock", rc.security_dir,
                                           security::kClockIdentity);
        // The clock speaks for the run: one line, not one per process.
        if (const std::string s = receive_buffer_shortfall(udp_receive_buffer_asked(*dds->participant()),
                                                           kernel_receive_buffer_cap());
            !s.empty())
            spdlog::warn("{}", s);
        tick_writer = dds->writer(topics::kTick, msg::message_ops<msg::Tick>(), kControlWriterProfile);
        control_writer = dds->writer(topics::kRunControl, msg::message_ops<msg::RunControl>(), kLatchedWriterProfile);
        status_writer = dds->writer(topics::kStatus, msg::message_ops<msg::ComponentStatus>(), kControlWriterProfile);
        done_reader = dds->reader(topics::kStepDone, msg::message_ops<msg::StepDone>(), kControlReaderProfile);
        status_reader = dds->reader(topics::kStatus, msg::message_ops<msg::ComponentStatus>(), kControlReaderProfile);
        fault_reader = dds->reader(topics::kFaultRequest, msg::message_ops<msg::FaultRequest>(), kControlReaderProfile);
        for (DataReader* r : {done_reader, status_reader, fault_reader}) {
            r->get_statuscondition().set_enabled_statuses(StatusMask::data_available());
            waitset.attach_condition(r->get_statuscondition());
        }
    }

    void heartbeat(double now);
    // clock_summary.yaml's rejected_samples (from the members' heartbeats); returns their total.
    std::uint64_t write_rejected(std::ostream& f) const;

    void send_tick(double now);

    void send_control(msg::RunCommand cmd, const std::string& reason);

    void read_status(double now);
    // A status of member `clock`: ours, a rival while claiming, else a foreign run's (ignored).
    void clock_status(const msg::ComponentStatus& s);
    // Whether a member's status belongs to this run (token 0: a member that has not joined yet).
    bool ours(const msg::ComponentStatus& s, double now);

    void read_done(double now);

    // Whether a taken control sample (StepDone, FaultRequest) is this run's: valid, of this run's index and token. A
    // sample of another token is noted as a foreign run's (`source` on `topic`).
    template <class Sample>
    bool this_run(const eprosima::fastdds::dds::SampleInfo& info, const Sample& s, const char* source,
                  const char* topic) {
        if (!info.valid_data || s.run_id() != rc.info.run_index) return false;
        if (s.run_token() != token) {
            foreign.note(s.run_token(), source, topic);
            return false;
        }
        return true;
    }

    bool aborted{false};
    std::string abort_reason;

    void declare_dead(Member& m, const std::string& why, double now);

    void check_liveness(double now);

    // Steps a member has completed, counting the steps a scheduled kill keeps it from (it is not stepped then).
    std::uint64_t effective_done(const Member& m) const;

    bool all_done() const;

    // Lowest number of steps that every live barrier member has completed.
    std::uint64_t min_done() const;

    std::string waiting_for() const;

    // An essential member killed by a scheduled fault at the step about to start ends the run, as its death would.
    // A fault injected live (gdnav fault): stamped with the first step no member can have reached, validated, sent
    // to every member; the run waits at the current step until all live members have adopted it.
    void read_fault_requests(double now);

    // A member declared dead is back (gdnav component --rejoin), matched with the others: it computes again from the
    // first step no member can have reached; every member learns it through a FAULTS schedule with a rejoin entry,
    // and the run waits until all (the newcomer too) have adopted it.
    void accept_rejoin(Member& m, const std::string& host, double now);

    bool all_adopted() const;

    void send_clock_status(msg::StatusKind kind, const std::string& message);

    // <out>/faults.yaml: the schedule as applied (the run config's faults and those injected live, with the step
    // they took effect at), for `gdnav run --faults FILE` to reproduce the run.
    void write_faults() const;

    // Members may be done beyond the kill step (the barrier skips a killed member): the run ends at the kill step.
    bool essential_killed();

    void gather(double now);

    // Members still missing before the table is sent: built-in ones within startup_timeout_s, external ones within
    // join_timeout_s (with a line every 5 s saying what the clock waits for). Returns true when the run must end.
    bool check_gather_timeouts(double now);

    bool everyone_ready();

    void log_progress(double now, bool force);

    bool write_summary(bool completed, double now);  // false: it could not be written (logged, told)

    int finish(int code, double now);

    int loop();
    // One pass of the loop in each phase: an exit code when the run ends, else kGoOn.
    static constexpr int kGoOn = -1;
    int claim_phase(double now);
    int gather_phase(double now);
    int configured_phase(double now);
    int running_phase(double now);
    // Every live member reported the step: the next Tick (now, or at its wall time when paced), or the end.
    int advance_tick(double now);
};

}  // namespace gdnav::dds
