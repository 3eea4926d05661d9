# Helpers that write PLCopen TC6 v2.01 elements (strun's own test inputs).
def conns(refs):
    out = []
    for r in refs:
        if isinstance(r, tuple): out.append(f'<connection refLocalId="{r[0]}" formalParameter="{r[1]}"/>')
        else: out.append(f'<connection refLocalId="{r}"/>')
    return "".join(out)
def pos(x, y): return f'<position x="{x}" y="{y}"/>'
def rail(i, x, y): return f'<leftPowerRail localId="{i}">{pos(x,y)}<connectionPointOut formalParameter=""/></leftPowerRail>'
def rrail(i, x, y, refs): return f'<rightPowerRail localId="{i}">{pos(x,y)}<connectionPointIn>{conns(refs)}</connectionPointIn></rightPowerRail>'
def contact(i, var, refs, x, y, neg=False, edge="none"):
    return (f'<contact localId="{i}" negated="{"true" if neg else "false"}" edge="{edge}">{pos(x,y)}'
            f'<connectionPointIn>{conns(refs)}</connectionPointIn><connectionPointOut/><variable>{var}</variable></contact>')
def coil(i, var, refs, x, y, neg=False, storage="none", edge="none"):
    return (f'<coil localId="{i}" negated="{"true" if neg else "false"}" storage="{storage}" edge="{edge}">{pos(x,y)}'
            f'<connectionPointIn>{conns(refs)}</connectionPointIn><connectionPointOut/><variable>{var}</variable></coil>')
def invar(i, expr, x, y, neg=False, order=None):
    o = f' executionOrderId="{order}"' if order is not None else ''
    return f'<inVariable localId="{i}" negated="{"true" if neg else "false"}"{o}>{pos(x,y)}<connectionPointOut/><expression>{expr}</expression></inVariable>'
def outvar(i, expr, refs, x, y, neg=False, order=None):
    o = f' executionOrderId="{order}"' if order is not None else ''
    return (f'<outVariable localId="{i}" negated="{"true" if neg else "false"}"{o}>{pos(x,y)}'
            f'<connectionPointIn>{conns(refs)}</connectionPointIn><expression>{expr}</expression></outVariable>')
def block(i, typ, ins, outs, x, y, inst=None, order=None):
    """ins: list of (name, refs, negated, edge); outs: list of (name, negated)"""
    a = f' instanceName="{inst}"' if inst else ''
    o = f' executionOrderId="{order}"' if order is not None else ''
    s = f'<block localId="{i}" typeName="{typ}"{a}{o}>{pos(x,y)}<inputVariables>'
    for n in ins:
        name, refs = n[0], n[1]
        neg = n[2] if len(n) > 2 else False
        edge = n[3] if len(n) > 3 else "none"
        s += f'<variable formalParameter="{name}" negated="{"true" if neg else "false"}" edge="{edge}"><connectionPointIn>{conns(refs)}</connectionPointIn></variable>'
    s += '</inputVariables><inOutVariables/><outputVariables>'
    for n in outs:
        name, neg = (n, False) if isinstance(n, str) else n
        s += f'<variable formalParameter="{name}" negated="{"true" if neg else "false"}"><connectionPointOut/></variable>'
    return s + '</outputVariables></block>'
def jump(i, label, refs, x, y): return f'<jump localId="{i}" label="{label}">{pos(x,y)}<connectionPointIn>{conns(refs)}</connectionPointIn></jump>'
def label(i, name, x, y): return f'<label localId="{i}" label="{name}">{pos(x,y)}</label>'
def ret(i, refs, x, y): return f'<return localId="{i}">{pos(x,y)}<connectionPointIn>{conns(refs)}</connectionPointIn></return>'
def connector(i, name, refs, x, y): return f'<connector localId="{i}" name="{name}">{pos(x,y)}<connectionPointIn>{conns(refs)}</connectionPointIn></connector>'
def continuation(i, name, x, y): return f'<continuation localId="{i}" name="{name}">{pos(x,y)}<connectionPointOut/></continuation>'
def var(name, typ, init=None):
    t = typ if typ.startswith('<') else f'<derived name="{typ}"/>'
    i = f'<initialValue><simpleValue value="{init}"/></initialValue>' if init is not None else ''
    return f'<variable name="{name}"><type>{t}</type>{i}</variable>'
def project(name, pous, task_interval="T#10ms", instances=()):
    s = ['<?xml version="1.0" encoding="utf-8"?>',
         '<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">',
         '  <fileHeader companyName="strun tests" productName="' + name + '" productVersion="1" creationDateTime="2026-11-27T10:00:00"/>',
         '  <contentHeader name="' + name + '"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>',
         '  <types><dataTypes/><pous>']
    s += pous
    s += ['  </pous></types>', '  <instances><configurations><configuration name="Plc"><resource name="Cpu">',
          f'    <task name="Cyclic" interval="{task_interval}" priority="1">']
    for inst, typ in instances:
        s.append(f'      <pouInstance name="{inst}" typeName="{typ}"/>')
    s += ['    </task>', '  </resource></configuration></configurations></instances>', '</project>']
    return "\n".join(s) + "\n"
def pou(name, kind, variables, lang, elements, extra_itf="", tail=""):
    s = [f'    <pou name="{name}" pouType="{kind}">', f'      <interface>{extra_itf}<localVars>']
    s += ['        ' + v for v in variables]
    s += ['      </localVars></interface>', f'      <body><{lang}>']
    s += ['        ' + e for e in elements]
    s += [f'      </{lang}></body>' + tail, '    </pou>']
    return s
