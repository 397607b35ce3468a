#!/bin/sh
# Sums the "N passed, N failed" last lines of the logs make test wrote (one
# per part, parts run in parallel), shows the failures, and ends with the
# total in the same form.  A part whose log is missing or does not end in
# that line (a build that broke) counts as one failure.
dir=$1
shift
passed=0
failed=0
for part in "$@"; do
    log="$dir/$part.log"
    last=$(tail -n 1 "$log" 2>/dev/null)
    case "$last" in
    *" passed, "*" failed")
        p=${last%% passed*}
        f=${last#*passed, }
        f=${f%% failed*}
        passed=$((passed + p))
        failed=$((failed + f))
        echo "$part: $last"
        if [ "$f" != 0 ]; then grep -E "FAIL|BAD|ERROR" "$log" | head -20; fi
        ;;
    *)
        failed=$((failed + 1))
        echo "$part: did not finish; the end of $log:"
        tail -n 15 "$log" 2>/dev/null
        ;;
    esac
done
if [ -f "$dir/start" ]; then
    echo "make test took $(( $(date +%s) - $(cat "$dir/start") )) s"
fi
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
