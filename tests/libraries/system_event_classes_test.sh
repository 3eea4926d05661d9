#!/bin/sh
# TwinCAT's own event classes beside a project's (decision 0400):
# TC_EVENT_CLASSES.TcSystemEventClass ... Win32EventClass exist in a TwinCAT
# folder that names the lists, Win32EventClass with its public GUID, the
# others with strun's ('STRN'); TC_EVENTS.TcSystemEventClass has the
# documented events (NoRTime = 2, Error) whose text the logger shows; the
# project's own classes are unchanged; FB_RequestEventClassName answers
# with the class' display name.
#   system_event_classes_test.sh STRUN TEST_SOURCE_DIR
set -eu
strun=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; echo "--- stderr"; cat "$tmp/err" 2>/dev/null; exit 1; }
cp -r "$src/event_classes" "$tmp/sys"
cat > "$tmp/sys/Plant/POUs/MAIN.TcPOU" <<'XML'
<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1"><POU Name="MAIN" Id="{7a1c2b44-0d6e-4f1a-9c55-1e2d3c4b5a69}">
<Declaration><![CDATA[PROGRAM MAIN
VAR
    win32Data1 : DWORD;
    systemData1 : DWORD;
    routerData4 : BYTE;
    noRTimeId : UDINT;
    noRTimeSeverity : TcEventSeverity;
    sameClass : BOOL;
    pumpStartedId : UDINT;
    msg : FB_TcMessage;
    text : STRING(255);
    req : FB_RequestEventClassName;
    className : STRING(255);
    pumpClassName : STRING(255);
    hr : HRESULT := 1;
END_VAR
]]></Declaration><Implementation><ST><![CDATA[
win32Data1 := TC_EVENT_CLASSES.Win32EventClass.Data1;
systemData1 := TC_EVENT_CLASSES.TcSystemEventClass.Data1;
routerData4 := TC_EVENT_CLASSES.TcRouterEventClass.Data4[7];
noRTimeId := TC_EVENTS.TcSystemEventClass.NoRTime.nEventId;
noRTimeSeverity := TC_EVENTS.TcSystemEventClass.NoRTime.eSeverity;
sameClass := F_strun_SameGuid(TC_EVENTS.TcSystemEventClass.NoRTime.uuidEventClass, TC_EVENT_CLASSES.TcSystemEventClass);
pumpStartedId := TC_EVENTS.PumpEvents.Started.nEventId;
msg.CreateEx(TC_EVENTS.TcSystemEventClass.TargetPortNotFound, 0);
msg.Send(0);
text := msg.sEventText;
hr := req.Request(TC_EVENT_CLASSES.TcSystemEventClass, 1033);
req.GetString(className, SIZEOF(className));
req.Request(TC_EVENT_CLASSES.PumpEvents, 1033);
req.GetString(pumpClassName, SIZEOF(pumpClassName));
]]></ST></Implementation></POU></TcPlcObject>
XML
"$strun" run --virtual --cycles 1 --dump "$tmp/sys" > "$tmp/dump.json" 2> "$tmp/err" || fail "the project did not run"
# 16#4ABEFBBF = 1254030271; 16#5354524E = 1398035022.
for expect in '"win32Data1": *1254030271,' '"systemData1": *1398035022,' '"routerData4": *3,' '"noRTimeId": *2,' \
    '"noRTimeSeverity": *"Error"' '"sameClass": *true' '"pumpStartedId": *1,' '"text": *"Target port not found"' \
    '"hr": 0' '"className": *"TwinCAT System"' '"pumpClassName": *"Pump station"'; do
    grep -q "$expect" "$tmp/dump.json" || fail "dump lacks $expect"
done
grep -q '^ADSLOG T#[0-9a-z#]* MainTask error: event 6 message: Target port not found$' "$tmp/err" || fail "log line"
echo PASS
