#include "live/modbus_plane.h"

#include <algorithm>

#include "runtime/scheduler.h"

namespace strun::live {

namespace {

ImageArea areaOf(rt::DirectAddress::Area area) {
    return area == rt::DirectAddress::Area::Input ? ImageArea::Inputs
           : area == rt::DirectAddress::Area::Output ? ImageArea::Outputs
                                                     : ImageArea::Memory;
}

}  // namespace

void ModbusPlane::requireServedTable() {
    control_.requireImageBytes(ImageArea::Inputs, 2 * kServedInputRegisters);  // %IW0..1023 (%IX0.0..1023.7 within)
    control_.requireImageBytes(ImageArea::Outputs, 2 * 1024);                  // %QW0..1023 (%QX0.0..1023.7 within)
    control_.requireImageBytes(ImageArea::Memory, 2 * (kServedHoldingRegisters - 1024));  // %MW0..1023
}

void ModbusPlane::requireMapped(const ModbusClientConfig& config) {
    for (const ModbusDevice& d : config.devices)
        for (const auto* list : {&d.reads, &d.writes})
            for (const MappedRange& r : *list) {
                size_t end = r.image.size == 'X' ? (r.image.byte * 8 + size_t(r.image.bit) + r.count + 7) / 8
                                                 : r.image.byte + 2 * size_t(r.count);
                control_.requireImageBytes(areaOf(r.image.area), end);
            }
}

void ModbusPlane::readImage(const std::function<void(const ImageView&)>& read) {
    std::shared_ptr<const Snapshot> snap = control_.latest();
    read(ImageView{snap->inputs.data(), snap->outputs.data(), snap->memory.data(), snap->inputs.size(), snap->outputs.size(),
                   snap->memory.size()});
}

void ModbusPlane::write(std::span<const ImageWrite> writes) {
    // One request's items (one poll's inputs) land in the same activation.
    std::vector<ControlPlane::NamedWrite> batch;
    batch.reserve(writes.size());
    for (const ImageWrite& w : writes)
        batch.push_back({rt::formatDirectAddress(w.at), w.at.size == 'X' ? (w.value ? "TRUE" : "FALSE") : std::to_string(w.value)});
    std::string error;
    // Cannot be refused: addresses inside the image and values of their types.
    control_.writeTogether(batch, error);
}

void ModbusPlane::ioFault(std::string message) {
    std::lock_guard<std::mutex> lock(faultsMutex_);
    faults_.push_back(std::move(message));
    faultsPending_.store(true, std::memory_order_release);
}

void ModbusPlane::runStarting(rt::Scheduler& scheduler) {
    scheduler_ = &scheduler;
    inner_.runStarting(scheduler);
}

void ModbusPlane::activationStarting(size_t task) {
    if (faultsPending_.load(std::memory_order_acquire) && scheduler_) {
        std::unique_lock<std::mutex> lock(faultsMutex_, std::try_to_lock);
        if (lock.owns_lock()) {
            recording_.swap(faults_);
            faultsPending_.store(false, std::memory_order_relaxed);
            lock.unlock();
            for (std::string& message : recording_) scheduler_->recordOutsideFault(rt::DiagCode::IoFault, std::move(message));
            recording_.clear();
        }
    }
    inner_.activationStarting(task);
}

}  // namespace strun::live
