#!/usr/bin/env python3
"""Writes the LD/FBD benchmark (logic.xml) and the same logic in ST (logic.st).

Program Ladder: 20 rungs, each a start/stop latch with a parallel branch
(M_k := (S_k OR M_k) AND NOT P_k), a negated coil and a set coil.
Program Blocks: 20 FBD networks, each y_k := SEL(GT(a*k + b, c), a, b + k).
The inputs change every cycle (an ST program Stim writes them), so the
work is the same in every cycle of both versions."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plcopen_elements import *

N = 20
B, I = '<BOOL/>', '<DINT/>'
lv, le, st_ld = [], [], []
for k in range(N):
    lv += [var(f'S{k}', B), var(f'P{k}', B), var(f'M{k}', B), var(f'NM{k}', B), var(f'L{k}', B)]
    base, y = 100 * k, 100 * k
    le += [rail(base + 1, 0, y), contact(base + 2, f'S{k}', [base + 1], 50, y), contact(base + 3, f'M{k}', [base + 1], 50, y + 30),
           contact(base + 4, f'P{k}', [base + 2, base + 3], 100, y, neg=True), coil(base + 5, f'M{k}', [base + 4], 150, y),
           coil(base + 6, f'NM{k}', [base + 4], 150, y + 30, neg=True), coil(base + 7, f'L{k}', [base + 4], 150, y + 60, storage='set')]
    st_ld.append(f'M{k} := (S{k} OR M{k}) AND NOT P{k}; NM{k} := NOT M{k}; IF M{k} THEN L{k} := TRUE; END_IF;')
fv, fe, st_fbd = [var('a', I), var('b', I), var('c', I)], [], []
for k in range(N):
    fv.append(var(f'y{k}', I))
    base, y = 100 * k, 100 * k
    fe += [invar(base + 1, 'a', 0, y), invar(base + 2, str(k + 1), 0, y + 20), invar(base + 3, 'b', 0, y + 40), invar(base + 4, 'c', 0, y + 60),
           block(base + 5, 'MUL', [('IN1', [base + 1]), ('IN2', [base + 2])], ['OUT'], 50, y),
           block(base + 6, 'ADD', [('IN1', [(base + 5, 'OUT')]), ('IN2', [base + 3])], ['OUT'], 100, y),
           block(base + 7, 'GT', [('IN1', [(base + 6, 'OUT')]), ('IN2', [base + 4])], ['OUT'], 150, y),
           invar(base + 8, 'a', 150, y + 30), invar(base + 9, 'b', 100, y + 60), invar(base + 10, str(k), 100, y + 80),
           block(base + 11, 'ADD', [('IN1', [base + 9]), ('IN2', [base + 10])], ['OUT'], 150, y + 60),
           block(base + 12, 'SEL', [('G', [(base + 7, 'OUT')]), ('IN0', [base + 8]), ('IN1', [(base + 11, 'OUT')])], ['OUT'], 200, y),
           outvar(base + 13, f'y{k}', [(base + 12, 'OUT')], 250, y)]
    st_fbd.append(f'y{k} := SEL(a * {k + 1} + b > c, a, b + {k});')

here = os.path.dirname(os.path.abspath(__file__))
pous = pou('Ladder', 'program', lv, 'LD', le) + pou('Blocks', 'program', fv, 'FBD', fe)
stim = ['    <pou name="Stim" pouType="program">', '      <interface><localVars>' + var('n', I) + '</localVars></interface>',
        '      <body><ST><xhtml:p><![CDATA[n := n + 1;\n' +
        '\n'.join(f'Ladder.S{k} := (n MOD {k + 2}) = 0; Ladder.P{k} := (n MOD {k + 3}) = 1;' for k in range(N)) +
        '\nBlocks.a := n MOD 100; Blocks.b := n MOD 37; Blocks.c := 50;]]></xhtml:p></ST></body>', '    </pou>']
open(os.path.join(here, 'logic.xml'), 'w').write(
    project('graphical_bench', stim + pous, instances=[('Stim', 'Stim'), ('Ladder', 'Ladder'), ('Blocks', 'Blocks')]))

def decl(vs):
    out = []
    for v in vs:
        name = v.split('"')[1]
        typ = 'BOOL' if '<BOOL/>' in v else 'DINT'
        out.append(f'    {name} : {typ};')
    return '\n'.join(out)
st = ['(* The logic of logic.xml written in ST (benchmarks/graphical/make_inputs.py). *)',
      'PROGRAM Stim', 'VAR n : DINT; END_VAR', 'n := n + 1;']
st += [f'Ladder.S{k} := (n MOD {k + 2}) = 0; Ladder.P{k} := (n MOD {k + 3}) = 1;' for k in range(N)]
st += ['Blocks.a := n MOD 100; Blocks.b := n MOD 37; Blocks.c := 50;', 'END_PROGRAM',
       'PROGRAM Ladder', 'VAR', decl(lv), 'END_VAR'] + st_ld + ['END_PROGRAM', 'PROGRAM Blocks', 'VAR', decl(fv), 'END_VAR'] + st_fbd + [
       'END_PROGRAM', 'CONFIGURATION Plc', 'RESOURCE Cpu ON PLC', 'TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 1);',
       'PROGRAM Stim WITH Cyclic : Stim;', 'PROGRAM Ladder WITH Cyclic : Ladder;', 'PROGRAM Blocks WITH Cyclic : Blocks;',
       'END_RESOURCE', 'END_CONFIGURATION']
open(os.path.join(here, 'logic.st'), 'w').write('\n'.join(st) + '\n')
