// Load for the Modbus server measurements (tests/modbus/measure.sh, not a
// test): CLIENTS libmodbus connections, each reading COUNT holding registers
// in a loop (RATE per second each, 0: as fast as answered) for SECONDS.
// Prints the requests answered per second, all clients together, and the
// failed ones.
//     modbus_load PORT CLIENTS SECONDS RATE [COUNT]
#include <modbus/modbus.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: modbus_load PORT CLIENTS SECONDS RATE [COUNT]\n");
        return 2;
    }
    int port = std::atoi(argv[1]), clients = std::atoi(argv[2]);
    double seconds = std::atof(argv[3]), rate = std::atof(argv[4]);
    int count = argc > 5 ? std::atoi(argv[5]) : 10;
    std::atomic<long> answered{0}, failed{0};
    auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    std::vector<std::thread> threads;
    for (int c = 0; c < clients; ++c)
        threads.emplace_back([&] {
            modbus_t* ctx = modbus_new_tcp("127.0.0.1", port);
            if (!ctx || modbus_connect(ctx) < 0) {
                failed++;
                return;
            }
            std::vector<uint16_t> regs(static_cast<size_t>(count));
            auto next = std::chrono::steady_clock::now();
            while (std::chrono::steady_clock::now() < end) {
                if (modbus_read_registers(ctx, 0, count, regs.data()) == count) answered++;
                else failed++;
                if (rate > 0) {
                    next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(1.0 / rate));
                    std::this_thread::sleep_until(next);
                }
            }
            modbus_close(ctx);
            modbus_free(ctx);
        });
    for (auto& t : threads) t.join();
    std::printf("requests/s %.0f failed %ld\n", double(answered) / seconds, long(failed));
    return 0;
}
