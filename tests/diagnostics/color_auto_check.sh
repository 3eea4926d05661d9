#!/bin/sh
# --color auto (decision 0160): colour only when stderr is a terminal, TERM is
# not "dumb" and NO_COLOR is unset. `script` gives strun a pseudo-terminal.
#   color_auto_check.sh STRUN PROGRAM.st
strun=$1 program=$2
esc=$(printf '\033[')
status=0
# TERM and NO_COLOR are set for each case so that the caller's environment does not matter.
run_in_terminal() {  # $1: environment assignments for strun
    script -qec "env $1 '$strun' check --color auto '$program'" /dev/null 2>&1
}
case "$(run_in_terminal '-u NO_COLOR TERM=xterm')" in
    *"$esc"*) ;;
    *) echo "a terminal with TERM=xterm: expected colour escapes"; status=1 ;;
esac
case "$(run_in_terminal 'TERM=xterm NO_COLOR=1')" in
    *"$esc"*) echo "NO_COLOR=1: expected no colour"; status=1 ;;
    *"error:"*) ;;
    *) echo "NO_COLOR=1: expected the diagnostic"; status=1 ;;
esac
case "$(run_in_terminal '-u NO_COLOR TERM=dumb')" in
    *"$esc"*) echo "TERM=dumb: expected no colour"; status=1 ;;
    *"error:"*) ;;
    *) echo "TERM=dumb: expected the diagnostic"; status=1 ;;
esac
# Not a terminal: never colour.
case "$(env -u NO_COLOR TERM=xterm "$strun" check --color auto "$program" 2>&1)" in
    *"$esc"*) echo "a pipe: expected no colour"; status=1 ;;
    *"error:"*) ;;
    *) echo "a pipe: expected the diagnostic"; status=1 ;;
esac
exit $status
