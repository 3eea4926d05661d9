/* C twin of case_machine.st (gcc -O2): CASE as switch, the enumeration as an enum. */
#include <stdint.h>
#include <stdio.h>

enum TokState { Idle, InNumber, InName, InString, Escape, InComment, Operator, Failed };

int main(void) {
    int32_t seed = 99, numbers = 0, names = 0, strings = 0, ops = 0, errors = 0, value = 0;
    enum TokState st = Idle;
    for (int32_t i = 1; i <= 6000000; ++i) {
        seed = (seed * 1103 + 12345) % 65536;
        int32_t sym = seed % 64, cls;
        if (sym <= 9) cls = 1;
        else if (sym <= 35) cls = 2;
        else if (sym == 36) cls = 3;
        else if (sym == 37) cls = 4;
        else if (sym <= 39) cls = 5;
        else if (sym <= 47) cls = 6;
        else if (sym <= 59) cls = 0;
        else cls = 7;
        switch (st) {
            case Idle:
                switch (cls) {
                    case 1: st = InNumber; value = sym; break;
                    case 2: st = InName; break;
                    case 3: st = InString; break;
                    case 5: st = InComment; break;
                    case 6: st = Operator; break;
                    case 4: st = Failed; break;
                }
                break;
            case InNumber:
                switch (cls) {
                    case 1: value = (value * 10 + sym) % 10007; break;
                    case 2: case 3: case 4: st = Failed; break;
                    default: numbers = numbers + 1; st = Idle; break;
                }
                break;
            case InName:
                switch (cls) {
                    case 1: case 2: break;
                    case 6: names = names + 1; st = Operator; break;
                    default: names = names + 1; st = Idle; break;
                }
                break;
            case InString:
                switch (cls) {
                    case 3: strings = strings + 1; st = Idle; break;
                    case 4: st = Escape; break;
                    case 7: st = Failed; break;
                }
                break;
            case Escape: st = InString; break;
            case InComment: if (cls == 7) st = Idle; break;
            case Operator:
                ops = ops + 1;
                switch (cls) {
                    case 1: st = InNumber; value = sym; break;
                    case 2: st = InName; break;
                    default: st = Idle; break;
                }
                break;
            case Failed:
                errors = errors + 1;
                if (cls == 0 || cls == 7) st = Idle;
                break;
        }
    }
    printf("%d\n", numbers * 7 + names * 5 + strings * 3 + ops * 2 + errors + value);
    return 0;
}
