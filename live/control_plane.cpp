#include "live/control_plane.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "interpreter/project/dump_json.h"
#include "interpreter/project/stimulus_build.h"
#include "interpreter/project/variable_path.h"

namespace strun::live {

namespace {

// Variables closer than this in memory share one copied region: fewer
// memcpy calls for a few bytes of padding copied in between.
constexpr size_t kRegionGap = 64;
// While a fault repeats every cycle, the diagnostic buffer is copied for
// the front ends at most this often (it can hold 1000 entries).
constexpr auto kDiagnosticCopyInterval = std::chrono::milliseconds(50);
// holdWhilePaused() looks at stop requests (Ctrl-C) this often.
constexpr auto kPauseCheck = std::chrono::milliseconds(20);

std::string upper(std::string_view s) { return sema::upper(std::string(s)); }

// "%Q0.1" is "%QX0.1": the key a force is matched by.
std::string addressKey(std::string_view name) {
    std::string key = upper(name);
    if (key.size() > 2 && key[0] == '%' && std::isdigit(static_cast<unsigned char>(key[2]))) key.insert(key.begin() + 2, 'X');
    return key;
}

}  // namespace

ControlPlane::ControlPlane(sema::ProgramModel& model, const rt::PlcProfile& profile, std::vector<rt::TaskSpec> specs,
                           std::string defaultStepTask)
    : model_(model), profile_(profile), specs_(std::move(specs)), defaultStepTask_(std::move(defaultStepTask)) {
    project::forEachElementary(model_, [&](const project::ElementaryVar& v) {
        LiveVariable var;
        var.path = v.ref.path;
        var.upperPath = upper(v.ref.path);
        var.type = v.ref.type;
        var.bit = v.ref.bit;
        var.size = v.ref.bit >= 0 ? 1 : std::max<size_t>(v.ref.type->size, 1);
        variables_.push_back(std::move(var));
        addresses_.push_back(v.ref.addr);
        return true;  // every variable
    });
    byUpperPath_.reserve(variables_.size());
    for (size_t i = 0; i < variables_.size(); ++i) byUpperPath_.emplace_back(variables_[i].upperPath, i);
    std::sort(byUpperPath_.begin(), byUpperPath_.end());
    const rt::ProcessImage& image = model_.machine.image;
    imageBytes_[size_t(ImageArea::Inputs)] = std::min(image.inputExtent, rt::ProcessImage::kSize);
    imageBytes_[size_t(ImageArea::Outputs)] = std::min(image.outputExtent, rt::ProcessImage::kSize);
    // %M has no extent of its own: as far as variables located there reach.
    const uint8_t* memory = image.memory.data();
    for (size_t i = 0; i < variables_.size(); ++i)
        if (addresses_[i] >= memory && addresses_[i] < memory + rt::ProcessImage::kSize)
            imageBytes_[size_t(ImageArea::Memory)] =
                std::max(imageBytes_[size_t(ImageArea::Memory)], size_t(addresses_[i] - memory) + variables_[i].size);
    planSnapshotLayout();
    timeline_ = std::make_unique<TimelineSlot[]>(kTimelineCapacity);
    cyclesSeen_.assign(specs_.size(), 0);
    allocateBuffers();
}

ControlPlane::~ControlPlane() {
    delete reinterpret_cast<Snapshot*>(middle_.load() & ~uintptr_t(1));
}

// Regions of memory that hold variables, merged when close, each with its
// place in Snapshot::data; every variable's offset follows from them.
void ControlPlane::planSnapshotLayout() {
    std::vector<size_t> order(variables_.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return addresses_[a] < addresses_[b]; });
    regions_.clear();
    dataSize_ = 0;
    for (size_t i : order) {
        const uint8_t* from = addresses_[i];
        const size_t size = variables_[i].size;
        if (!regions_.empty()) {
            Region& last = regions_.back();
            const uint8_t* lastEnd = last.from + last.size;
            if (from >= last.from && from <= lastEnd + kRegionGap) {
                if (from + size > lastEnd) {
                    size_t grow = size_t(from + size - lastEnd);
                    last.size += grow;
                    dataSize_ += grow;
                }
                variables_[i].offset = last.offset + size_t(from - last.from);
                continue;
            }
        }
        regions_.push_back({from, size, dataSize_});
        variables_[i].offset = dataSize_;
        dataSize_ += size;
    }
}

void ControlPlane::allocateBuffers() {
    auto make = [&] {
        auto snap = std::make_unique<Snapshot>();
        snap->data.resize(dataSize_);
        snap->inputs.resize(imageBytes_[0]);
        snap->outputs.resize(imageBytes_[1]);
        snap->memory.resize(imageBytes_[2]);
        snap->tasks.resize(specs_.size());
        for (size_t i = 0; i < specs_.size(); ++i) snap->tasks[i].kind = specs_[i].kind;
        return snap;
    };
    back_ = make();
    front_ = make();
    delete reinterpret_cast<Snapshot*>(middle_.exchange(reinterpret_cast<uintptr_t>(make().release())) & ~uintptr_t(1));
    // Before the first activation front ends see the initial values.
    fillSnapshot(*front_, false);
    front_->sequence = 0;
    std::lock_guard<std::mutex> lock(readerMutex_);
    latestCopy_ = std::make_shared<const Snapshot>(*front_);
}

void ControlPlane::requireImageBytes(ImageArea area, size_t bytes) {
    size_t& have = imageBytes_[size_t(area)];
    bytes = std::min(bytes, rt::ProcessImage::kSize);
    if (bytes <= have) return;
    have = bytes;
    allocateBuffers();
}

void ControlPlane::startPaused() { paused_.store(true, std::memory_order_release); }

const LiveVariable* ControlPlane::findVariable(std::string_view path) const {
    std::string key = upper(path);
    auto it = std::lower_bound(byUpperPath_.begin(), byUpperPath_.end(), key,
                               [](const std::pair<std::string, size_t>& e, const std::string& k) { return e.first < k; });
    if (it == byUpperPath_.end() || it->first != key) return nullptr;
    return &variables_[it->second];
}

const LiveVariable* ControlPlane::variableAt(const uint8_t* address, int bit) const {
    for (size_t i = 0; i < variables_.size(); ++i)
        if (addresses_[i] == address && variables_[i].bit == bit) return &variables_[i];
    return nullptr;
}

// ---------------------------------------------------------------- snapshots

void ControlPlane::fillSnapshot(Snapshot& snap, bool ended) {
    for (const Region& r : regions_) std::memcpy(snap.data.data() + r.offset, r.from, r.size);
    const rt::ProcessImage& image = model_.machine.image;
    // An empty image has no storage: memcpy of zero bytes from null is still undefined.
    if (!snap.inputs.empty()) std::memcpy(snap.inputs.data(), image.inputs.data(), snap.inputs.size());
    if (!snap.outputs.empty()) std::memcpy(snap.outputs.data(), image.outputs.data(), snap.outputs.size());
    if (!snap.memory.empty()) std::memcpy(snap.memory.data(), image.memory.data(), snap.memory.size());
    snap.ended = ended;
    if (scheduler_) {
        snap.time = ended ? scheduler_->endTime() : scheduler_->now();
        snap.state = scheduler_->state();
        scheduler_->copyTaskStats(snap.tasks);
        snap.diagnosticsTotal = scheduler_->diagnostics().size() + scheduler_->droppedDiagnostics();
    }
}

void ControlPlane::publish(bool ended) {
    fillSnapshot(*back_, ended);
    back_->sequence = sequence_.load(std::memory_order_relaxed) + 1;
    uintptr_t old = middle_.exchange(reinterpret_cast<uintptr_t>(back_.release()) | 1, std::memory_order_acq_rel);
    back_.reset(reinterpret_cast<Snapshot*>(old & ~uintptr_t(1)));
    sequence_.fetch_add(1, std::memory_order_release);
    copyDiagnostics(ended);
    // Without the lock: a waiter that just missed this wakes at its timeout.
    waitCv_.notify_all();
}

// The diagnostic buffer for front ends, when it changed (never waiting: a
// reader holding the lock only delays the copy to a later activation).
void ControlPlane::copyDiagnostics(bool force) {
    if (!scheduler_) return;
    uint64_t total = scheduler_->diagnostics().size() + scheduler_->droppedDiagnostics();
    if (total == diagSeenTotal_) return;
    auto now = std::chrono::steady_clock::now();
    if (!force && now - lastDiagCopy_ < kDiagnosticCopyInterval) return;
    std::unique_lock<std::mutex> lock(diagMutex_, std::defer_lock);
    if (force) lock.lock();
    else if (!lock.try_lock()) return;
    diagCopy_ = scheduler_->diagnostics();
    diagDropped_ = scheduler_->droppedDiagnostics();
    diagSeenTotal_ = total;
    lastDiagCopy_ = now;
}

std::shared_ptr<const Snapshot> ControlPlane::latest() {
    std::lock_guard<std::mutex> lock(readerMutex_);
    if (middle_.load(std::memory_order_acquire) & 1) {
        uintptr_t got = middle_.exchange(reinterpret_cast<uintptr_t>(front_.release()), std::memory_order_acq_rel);
        front_.reset(reinterpret_cast<Snapshot*>(got & ~uintptr_t(1)));
        latestCopy_ = std::make_shared<const Snapshot>(*front_);
    }
    return latestCopy_;
}

bool ControlPlane::waitForSnapshot(uint64_t seen, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(waitMutex_);
    return waitCv_.wait_for(lock, timeout, [&] { return sequence() > seen || ended(); }) && sequence() > seen;
}

nlohmann::ordered_json ControlPlane::valueJson(const Snapshot& snap, const LiveVariable& var) {
    const uint8_t* p = snap.data.data() + var.offset;
    if (var.bit >= 0) return ((*p >> var.bit) & 1) != 0;
    return project::valueToJson(var.type, p);
}

std::vector<rt::DiagEntry> ControlPlane::diagnostics(uint64_t* dropped) const {
    std::lock_guard<std::mutex> lock(diagMutex_);
    if (dropped) *dropped = diagDropped_;
    return diagCopy_;
}

PlcTime ControlPlane::endTime() const { return endTime_; }

// ---------------------------------------------------------------- writes and forces

bool ControlPlane::resolve(std::string_view name, std::string_view literal, Target& out, std::string& error) const {
    project::StimulusEntry entry{0, std::string(name), std::string(literal), std::string()};
    project::ResolvedWrite resolved;
    {
        std::lock_guard<std::mutex> lock(resolveMutex_);
        if (!project::resolveWrite(model_, entry, resolved, error, profile_, project::WriteScope::Anywhere)) return false;
    }
    const rt::StimulusWrite& w = resolved.write;
    out.name = resolved.name;
    out.key = addressKey(resolved.name);
    out.type = resolved.type;
    out.dest = w.dest;
    out.input = w.kind == rt::StimulusWrite::Kind::PhysicalInput;
    out.forceDest = out.input ? model_.machine.image.inputs.data() + w.inputOffset : w.dest;
    out.bit = w.bit;
    out.bytes = w.bytes;
    return true;
}

void ControlPlane::enqueue(Request request) {
    std::lock_guard<std::mutex> lock(requestMutex_);
    requests_.push_back(std::move(request));
    requestsPending_.store(true, std::memory_order_release);
}

bool ControlPlane::writeTogether(const std::vector<NamedWrite>& writes, std::string& error) {
    std::vector<Request> batch(writes.size());
    for (size_t i = 0; i < writes.size(); ++i) {
        if (!resolve(writes[i].name, writes[i].literal, batch[i].target, error)) return false;
        batch[i].kind = Request::Kind::Write;
    }
    // One lock for the whole batch: drainRequests() takes all of it or none.
    std::lock_guard<std::mutex> lock(requestMutex_);
    for (Request& r : batch) requests_.push_back(std::move(r));
    requestsPending_.store(true, std::memory_order_release);
    return true;
}

bool ControlPlane::write(std::string_view name, std::string_view literal, std::string& error) {
    Request r;
    if (!resolve(name, literal, r.target, error)) return false;
    r.kind = Request::Kind::Write;
    enqueue(std::move(r));
    return true;
}

bool ControlPlane::force(std::string_view name, std::string_view literal, std::string& error) {
    Request r;
    if (!resolve(name, literal, r.target, error)) return false;
    r.kind = Request::Kind::Force;
    {
        std::lock_guard<std::mutex> lock(forcesMutex_);
        auto it = std::find_if(shownForces_.begin(), shownForces_.end(), [&](const Target& t) { return t.key == r.target.key; });
        if (it != shownForces_.end()) *it = r.target;
        else shownForces_.push_back(r.target);
    }
    enqueue(std::move(r));
    return true;
}

bool ControlPlane::forceAtStart(std::string_view name, std::string_view literal, std::string& error) {
    Target t;
    if (!resolve(name, literal, t, error)) return false;
    std::lock_guard<std::mutex> lock(forcesMutex_);
    auto same = [&](const Target& f) { return f.key == t.key; };
    shownForces_.erase(std::remove_if(shownForces_.begin(), shownForces_.end(), same), shownForces_.end());
    activeForces_.erase(std::remove_if(activeForces_.begin(), activeForces_.end(), same), activeForces_.end());
    shownForces_.push_back(t);
    activeForces_.push_back(std::move(t));
    return true;
}

// The key a force on NAME is kept under, without a value to resolve.
bool ControlPlane::canonicalKey(std::string_view name, std::string& key, std::string& error) const {
    std::string text(name);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.erase(text.begin());
    // A target's input alias (FI0) is kept under its own name, as resolveWrite names it.
    if (rt::findInputAlias(profile_, text) || (!text.empty() && text[0] == '%')) {
        key = addressKey(text);
        return true;
    }
    std::lock_guard<std::mutex> lock(resolveMutex_);
    auto ref = project::resolveVariablePath(model_, text, error);
    if (!ref) return false;
    key = upper(ref->path);
    return true;
}

bool ControlPlane::unforce(std::string_view name, std::string& error) {
    std::string key;
    if (!canonicalKey(name, key, error)) return false;
    {
        std::lock_guard<std::mutex> lock(forcesMutex_);
        auto it = std::find_if(shownForces_.begin(), shownForces_.end(), [&](const Target& t) { return t.key == key; });
        if (it == shownForces_.end()) return true;  // not forced: nothing to release
        shownForces_.erase(it);
    }
    Request r;
    r.kind = Request::Kind::Unforce;
    r.target.key = key;
    enqueue(std::move(r));
    return true;
}

void ControlPlane::unforceAll() {
    {
        std::lock_guard<std::mutex> lock(forcesMutex_);
        shownForces_.clear();
    }
    Request r;
    r.kind = Request::Kind::UnforceAll;
    enqueue(std::move(r));
}

std::vector<ForceInfo> ControlPlane::forces() const {
    std::lock_guard<std::mutex> lock(forcesMutex_);
    std::vector<ForceInfo> out;
    for (const Target& t : shownForces_) out.push_back({t.name, t.type, t.bytes});
    return out;
}

nlohmann::ordered_json ControlPlane::forcesJson() const {
    nlohmann::ordered_json obj = nlohmann::ordered_json::object();
    for (const ForceInfo& f : forces()) obj[f.name] = project::valueToJson(f.type, f.bytes.data());
    return obj;
}

// The scheduler takes queued requests without ever waiting for the lock.
void ControlPlane::drainRequests() {
    if (!requestsPending_.load(std::memory_order_acquire)) return;
    {
        std::unique_lock<std::mutex> lock(requestMutex_, std::try_to_lock);
        if (!lock) return;  // a front end is queueing right now: next activation
        draining_.swap(requests_);
        requestsPending_.store(false, std::memory_order_relaxed);
    }
    bool inputsChanged = false;
    for (Request& r : draining_) {
        auto same = [&](const Target& f) { return f.key == r.target.key; };
        switch (r.kind) {
        case Request::Kind::Write: {
            const size_t n = r.target.bit >= 0 ? 1 : r.target.bytes.size();
            uint8_t before[8] = {};
            if (r.target.input) std::memcpy(before, r.target.dest, std::min<size_t>(n, sizeof before));
            store(r.target, r.target.dest);
            if (r.target.input && std::memcmp(before, r.target.dest, std::min<size_t>(n, sizeof before)) != 0) inputsChanged = true;
            break;
        }
        case Request::Kind::Force: {
            auto it = std::find_if(activeForces_.begin(), activeForces_.end(), same);
            if (it != activeForces_.end()) *it = std::move(r.target);
            else activeForces_.push_back(std::move(r.target));
            break;
        }
        case Request::Kind::Unforce:
            activeForces_.erase(std::remove_if(activeForces_.begin(), activeForces_.end(), same), activeForces_.end());
            break;
        case Request::Kind::UnforceAll: activeForces_.clear(); break;
        }
    }
    draining_.clear();
    // As a --set write to an input does: EXTERNAL tasks see the edge.
    if (inputsChanged && running_) running_->physicalInputsChanged(running_->now());
}

void ControlPlane::store(const Target& t, uint8_t* dest) {
    if (t.bit >= 0) {
        uint8_t mask = uint8_t(1u << t.bit);
        *dest = (!t.bytes.empty() && t.bytes[0]) ? uint8_t(*dest | mask) : uint8_t(*dest & ~mask);
    } else {
        if (!t.bytes.empty()) std::memcpy(dest, t.bytes.data(), t.bytes.size());
    }
}

void ControlPlane::applyForces(bool inputsOnly, bool skipInputs) {
    for (const Target& t : activeForces_) {
        if ((inputsOnly && !t.input) || (skipInputs && t.input)) continue;
        store(t, t.forceDest);
    }
}

// ---------------------------------------------------------------- pause and step

void ControlPlane::pause() {
    paused_.store(true, std::memory_order_release);
}

void ControlPlane::resume() {
    {
        std::lock_guard<std::mutex> lock(controlMutex_);
        stepTask_.store(-1, std::memory_order_release);
        paused_.store(false, std::memory_order_release);
    }
    controlCv_.notify_all();
}

bool ControlPlane::startStep(std::string_view task, uint64_t cycles, std::string& error) {
    std::string name(task.empty() ? std::string_view(defaultStepTask_) : task);
    int64_t index = -1;
    for (size_t i = 0; i < specs_.size(); ++i)
        if (upper(specs_[i].name) == upper(name)) index = int64_t(i);
    if (index < 0) {
        error = specs_.empty() ? "the project has no task to step" : "no task named '" + name + "'";
        return false;
    }
    if (cycles == 0) {
        error = "cycles must be at least 1";
        return false;
    }
    {
        std::lock_guard<std::mutex> lock(controlMutex_);
        stepRemaining_.store(cycles, std::memory_order_relaxed);
        stepTask_.store(index, std::memory_order_release);
        paused_.store(false, std::memory_order_release);
    }
    controlCv_.notify_all();
    return true;
}

bool ControlPlane::waitUntilPaused(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(controlMutex_);
    return controlCv_.wait_for(lock, timeout, [&] { return (holding_ && paused()) || ended(); });
}

// ---------------------------------------------------------------- timeline

std::vector<TimelineEvent> ControlPlane::timeline(uint64_t from) const {
    std::vector<TimelineEvent> out;
    uint64_t next = timelineNext_.load(std::memory_order_acquire);
    if (next > kTimelineCapacity) from = std::max(from, next - kTimelineCapacity);
    for (uint64_t i = from; i < next; ++i) {
        const TimelineSlot& slot = timeline_[i % kTimelineCapacity];
        uint64_t tag = slot.tag.load(std::memory_order_acquire);
        int64_t time = slot.time.load(std::memory_order_relaxed);
        std::atomic_thread_fence(std::memory_order_acquire);
        if (slot.tag.load(std::memory_order_relaxed) != tag || (tag >> 17) != i) continue;  // overwritten meanwhile
        out.push_back({i, time, uint32_t((tag >> 1) & 0xFFFF), (tag & 1) != 0});
    }
    return out;
}

// ---------------------------------------------------------------- the scheduler's side

void ControlPlane::runStarting(rt::Scheduler& scheduler) {
    scheduler_ = &scheduler;
    running_ = &scheduler;
}

bool ControlPlane::holdWhilePaused() {
    if (!paused_.load(std::memory_order_acquire)) return false;
    std::unique_lock<std::mutex> lock(controlMutex_);
    if (!paused_.load(std::memory_order_acquire)) return false;
    holding_ = true;
    controlCv_.notify_all();
    // The lock is released while waiting: front ends resume or step meanwhile.
    while (paused_.load(std::memory_order_acquire) && !rt::Scheduler::stopRequested()) controlCv_.wait_for(lock, kPauseCheck);
    holding_ = false;
    return true;
}

void ControlPlane::activationStarting(size_t) {
    drainRequests();
    applyForces(false, true);
}

void ControlPlane::inputsLatched(size_t) {
    if (!activeForces_.empty()) applyForces(true, false);
}

void ControlPlane::activationEnding(size_t) {
    if (!activeForces_.empty()) applyForces(false, false);
}

void ControlPlane::activationEnded(size_t task, bool, bool outermost) {
    if (task < cyclesSeen_.size() && scheduler_) {
        uint64_t cycles = scheduler_->cyclesOf(task);
        bool counted = cycles != cyclesSeen_[task];
        cyclesSeen_[task] = cycles;
        if (counted && stepTask_.load(std::memory_order_acquire) == int64_t(task) &&
            stepRemaining_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            stepTask_.store(-1, std::memory_order_relaxed);
            paused_.store(true, std::memory_order_release);
        }
    }
    if (outermost) publish(false);
}

void ControlPlane::taskRunning(size_t task, bool running, PlcTime now) {
    uint64_t i = timelineNext_.load(std::memory_order_relaxed);
    TimelineSlot& slot = timeline_[i % kTimelineCapacity];
    slot.tag.store(~uint64_t(0), std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    slot.time.store(now, std::memory_order_relaxed);
    slot.tag.store((i << 17) | (uint64_t(task & 0xFFFF) << 1) | (running ? 1 : 0), std::memory_order_release);
    timelineNext_.store(i + 1, std::memory_order_release);
}

void ControlPlane::runEnded(const rt::Scheduler& scheduler) {
    scheduler_ = &scheduler;
    running_ = nullptr;
    endTime_ = scheduler.endTime();
    publish(true);
    {
        std::lock_guard<std::mutex> lock(controlMutex_);
        ended_.store(true, std::memory_order_release);
    }
    controlCv_.notify_all();
    waitCv_.notify_all();
}

}  // namespace strun::live
