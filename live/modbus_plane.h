// The Modbus threads' view of a live run (live/modbus_plc.h) over the live
// control plane (live/control_plane.h): reads from its latest snapshot,
// writes through its write queue (the contract's live writes), and IO_FAULT
// into the scheduler's diagnostic buffer.
//
// The control plane has no way for a front end to record a diagnostic, so
// this class stands between the scheduler and the plane as the run's
// rt::LiveHooks: every hook is passed on unchanged; at an activation start
// it first records the IO_FAULTs queued since (try_lock only: the scan never
// waits for a Modbus thread; a fault that finds the queue busy is recorded
// at the next activation).
#pragma once

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include "live/control_plane.h"
#include "live/modbus_map.h"
#include "live/modbus_plc.h"
#include "runtime/live_hooks.h"

namespace strun::live {

class ModbusPlane final : public ModbusPlc, public rt::LiveHooks {
public:
    // `hooks`: what the run had as RunOptions::live (the control plane); the
    // caller then sets RunOptions::live to this object.
    ModbusPlane(ControlPlane& control, rt::LiveHooks& hooks) : control_(control), inner_(hooks) {}

    // Before the run: the snapshots carry the image bytes the server's table
    // and the client's mapping reach, even where the program addresses none.
    void requireServedTable();
    void requireMapped(const ModbusClientConfig& config);

    // ModbusPlc (network threads)
    void readImage(const std::function<void(const ImageView&)>& read) override;
    void write(std::span<const ImageWrite> writes) override;
    void ioFault(std::string message) override;

    // rt::LiveHooks (the scheduler's thread)
    void runStarting(rt::Scheduler& scheduler) override;
    bool holdWhilePaused() override { return inner_.holdWhilePaused(); }
    void activationStarting(size_t task) override;
    void inputsLatched(size_t task) override { inner_.inputsLatched(task); }
    void activationEnding(size_t task) override { inner_.activationEnding(task); }
    void activationEnded(size_t task, bool completed, bool outermost) override { inner_.activationEnded(task, completed, outermost); }
    void taskRunning(size_t task, bool running, PlcTime now) override { inner_.taskRunning(task, running, now); }

private:
    ControlPlane& control_;
    rt::LiveHooks& inner_;
    rt::Scheduler* scheduler_ = nullptr;
    std::mutex faultsMutex_;
    std::vector<std::string> faults_;  // under faultsMutex_
    std::atomic<bool> faultsPending_{false};
    std::vector<std::string> recording_;  // scheduler-owned
};

}  // namespace strun::live
