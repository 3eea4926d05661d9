"""A water tank as a Modbus TCP device (pymodbus): the plant that
tank_control.st controls through `strun run --modbus-client mapping.json`.

    python3 plant.py [PORT] [SECONDS]      (default 5020, run until killed)

Tables (addresses 0-based, unit id 1):
  coil 0              inflow pump (written by the PLC)
  coil 1              drain valve (written by the PLC)
  discrete input 0    low level switch  (level < 20 %)
  discrete input 1    high level switch (level > 80 %)
  input register 0    level in 0.1 % (0..1000)
  input register 1    outflow demand in 0.1 %/s (a consumer that changes)
The physics runs every 50 ms: the pump adds 8 %/s, the drain valve takes
6 %/s, the consumer takes 1..3 %/s. Once a second a line on stdout shows the
state: that is the plant being controlled."""
import asyncio
import math
import sys
import time

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusServerContext, ModbusSlaveContext
from pymodbus.server import StartAsyncTcpServer

PUMP_RATE, DRAIN_RATE = 8.0, 6.0  # % per second


async def physics(slave, seconds):
    level = 50.0
    start = last = time.monotonic()
    shown = 0
    while seconds <= 0 or time.monotonic() - start < seconds:
        await asyncio.sleep(0.05)
        now = time.monotonic()
        dt, last = now - last, now
        pump, drain = slave.getValues(1, 0, 2)  # function 1: coils
        demand = 2.0 + math.sin((now - start) / 3.0)  # the consumer, 1..3 %/s
        level += dt * ((PUMP_RATE if pump else 0.0) - (DRAIN_RATE if drain else 0.0) - demand)
        level = min(100.0, max(0.0, level))
        slave.setValues(2, 0, [level < 20.0, level > 80.0])        # function 2: discrete inputs
        slave.setValues(4, 0, [int(level * 10), int(demand * 10)])  # function 4: input registers
        if now - start >= shown:
            print("t=%4.1fs level=%5.1f%% pump=%s drain=%s" % (now - start, level, "ON " if pump else "off",
                                                              "OPEN" if drain else "shut"), flush=True)
            shown += 1


async def serve(server, slave, seconds):
    """Serves until the physics ends (SECONDS), or forever."""
    physics_task = asyncio.create_task(physics(slave, seconds))
    serving = asyncio.create_task(server.serve_forever())
    await asyncio.wait([physics_task, serving], return_when=asyncio.FIRST_COMPLETED)


async def main():
    port = int(sys.argv[1]) if len(sys.argv) > 1 else 5020
    seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 0
    slave = ModbusSlaveContext(di=ModbusSequentialDataBlock(0, [0] * 16), co=ModbusSequentialDataBlock(0, [0] * 16),
                               hr=ModbusSequentialDataBlock(0, [0] * 16), ir=ModbusSequentialDataBlock(0, [0] * 16),
                               zero_mode=True)
    server = await StartAsyncTcpServer(ModbusServerContext(slaves=slave, single=True), address=("127.0.0.1", port),
                                       defer_start=True)
    print("plant: tank on modbus tcp://127.0.0.1:%d/" % port, flush=True)
    await serve(server, slave, seconds)


asyncio.run(main())
