"""A Modbus TCP device for the tests: pymodbus's server over four tables
(zero-based addresses) with the values given on the command line.

    device.py PORT '{"di": [1,0,1], "co": [], "hr": [], "ir": [111, 222]}'

Runs until killed; prints "ready" on stdout once it listens."""
import asyncio
import json
import sys

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusServerContext, ModbusSlaveContext
from pymodbus.server import StartAsyncTcpServer


def block(values, size=256):
    data = list(values) + [0] * (size - len(values))
    return ModbusSequentialDataBlock(0, data)


async def main():
    port = int(sys.argv[1])
    init = json.loads(sys.argv[2]) if len(sys.argv) > 2 else {}
    slave = ModbusSlaveContext(di=block(init.get("di", [])), co=block(init.get("co", [])),
                               hr=block(init.get("hr", [])), ir=block(init.get("ir", [])), zero_mode=True)
    context = ModbusServerContext(slaves=slave, single=True)
    server = await StartAsyncTcpServer(context, address=("127.0.0.1", port), defer_start=True)
    print("ready", flush=True)
    await server.serve_forever()


asyncio.run(main())
