#!/bin/sh
# capbridge command-line errors: exit status 2 and one line on stderr that names what is
# wrong (and what is allowed); --help; run-time failures exit 1 with the core's message.
. "$(dirname "$0")/lib.sh"

# expect CODE LABEL NEEDLE... -- ARGUMENTS...: the exit status, and for CODE 2 one line on
# stderr holding every NEEDLE
expect() {
    want=$1 label=$2
    shift 2
    needles=
    while [ "$1" != "--" ]; do
        needles="$needles
$1"
        shift
    done
    shift
    "$CB" "$@" >"$TMP/out" 2>"$TMP/err" </dev/null
    code=$?
    checks=$((checks + 1))
    [ "$code" -eq "$want" ] || { fail "$label: exit $code, expected $want ($(cat "$TMP/err"))"; return; }
    if [ "$want" -eq 2 ]; then
        checks=$((checks + 1))
        [ "$(wc -l <"$TMP/err")" -eq 1 ] || fail "$label: stderr is not one line: $(head -c 600 "$TMP/err")"
        checks=$((checks + 1))
        [ "$(wc -c <"$TMP/err")" -le 400 ] || fail "$label: $(wc -c <"$TMP/err") bytes on stderr: $(head -c 600 "$TMP/err")"
        checks=$((checks + 1))
        [ ! -s "$TMP/out" ] || fail "$label: printed on stdout: $(head -2 "$TMP/out")"
    fi
    printf '%s\n' "$needles" | while IFS= read -r needle; do
        [ -n "$needle" ] || continue
        grep -qF -- "$needle" "$TMP/err" || echo "stderr lacks '$needle': $(cat "$TMP/err")"
    done >"$TMP/why"
    checks=$((checks + 1))
    [ ! -s "$TMP/why" ] || fail "$label: $(head -c 600 "$TMP/why")"
}

G="--r1 1e-3 --r2 1e-3 --volume 1e-11"
LAWS="richefeu, willett, willett/reduced, rabinovich, rabinovich/uncorrected, weigert, soulie, table"

# user text in a message is cut to its first 60 bytes, with its length, and a control
# character is shown as \xHH: the message stays one short line (a 100 kB argument was
# echoed whole)
LONG=$(awk 'BEGIN { s = "x"; while (length(s) < 100000) s = s s; print substr(s, 1, 100000) }')
ONES=$(printf '%s' "$LONG" | tr x 1)
ZEROS=$(printf '%s' "$LONG" | tr x 0)
X60=$(printf '%s' "$LONG" | cut -c1-60)
expect 2 "a 100 kB subcommand" "unknown subcommand '$X60...' (100000 bytes): allowed force, curve" -- "$LONG"
expect 2 "a subcommand with a newline" "unknown subcommand 'for\x0ace': allowed" -- "for
ce"
expect 2 "a 100 kB subcommand after help" "unknown subcommand '$X60...' (100000 bytes)" -- help "$LONG"
expect 2 "a 100 kB option" "unknown option '--$(printf '%s' "$X60" | cut -c1-58)...' (100002 bytes): allowed --r1" -- force richefeu $G --gap 0 "--$LONG"
expect 2 "a 100 kB option with =" "unknown option '--gapxxxxxxx" "...' (100005 bytes)" -- force richefeu $G "--gap$LONG=0"
expect 2 "a 100 kB argument" "unexpected argument '$X60...' (100000 bytes): law keywords go right after" -- force richefeu $G --gap 0 "$LONG"
expect 2 "a 100 kB number" "option --gap: '1$(printf '%s' "$X60" | cut -c1-59)...' (100001 bytes) is not a decimal number" -- force richefeu $G --gap "1$LONG"
expect 2 "a 100 kB negative radius" "option --r1: -0000000000" "... (100003 bytes) must be > 0" -- force richefeu --r1 "-0${ZEROS}1" --r2 1e-3 --volume 1e-11 --gap 0
expect 2 "a 100 kB whole number" "option --points: '1111111111" "...' (100000 bytes) is not a whole number" -- curve richefeu $G --points "$ONES"
expect 2 "a 100 kB text" "no configuration named '$X60...' (100000 bytes) in cases" -- reference cases --only "$LONG"
expect 2 "a 100 kB set" "unknown set '$X60...' (100000 bytes): allowed cases, grid" -- reference "$LONG"
expect 2 "a 100 kB argument of bench" "unknown argument '$X60...' (100000 bytes): bench takes none" -- bench "$LONG"
expect 2 "a 100 kB argument of report" "unknown option or missing value '$X60...' (100000 bytes): allowed --reference DIR, --csv FILE" -- report "$LONG"
expect 1 "a 100 kB replay file name" "cannot open '$X60...' (100000 bytes)" -- replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5 "$LONG"
# a UTF-8 character is not cut in two: 59 x then a 2-byte character at bytes 60-61
expect 2 "a long name cut before a UTF-8 character" "unknown subcommand '$(printf '%s' "$X60" | cut -c1-59)...' (100061 bytes)" -- "$(printf '%s' "$X60" | cut -c1-59)é$LONG"

# subcommands
expect 2 "no subcommand" "missing subcommand" "force, curve, rupture, exact, pulloff, replay" --
expect 2 "unknown subcommand" "unknown subcommand 'forse'" "allowed force, curve" -- forse richefeu $G --gap 0
expect 2 "help for an unknown subcommand" "unknown subcommand 'bogus'" -- help bogus

# the law and its keywords
expect 2 "unknown law" "unknown law 'wilet'" "allowed $LAWS" -- force wilet $G --gap 0
expect 2 "missing law" "missing law" "$LAWS" -- force $G --gap 0
expect 2 "a 100 kB law name" "unknown law '$X60...' (100000 bytes)" -- force "$LONG" $G --gap 0
expect 2 "a repeated law keyword" "keyword 'gamma' given twice: each law keyword may be given once" -- force richefeu gamma 0.07 gamma 0.08 $G --gap 0
expect 2 "a repeated law keyword after others" "keyword 'theta' given twice" -- rupture willett theta 10 gamma 0.07 theta 20 --r1 1e-3 --r2 1e-3 --volume 1e-12
expect 2 "unknown keyword" "unknown keyword 'gama'" "allowed gamma, theta, rupture, overlap, validity, viscosity, min_gap, c" -- force richefeu gama 0.07 $G --gap 0
expect 2 "a negative viscosity" "viscosity '-1': give the liquid's viscosity in Pa s, >= 0" -- force richefeu viscosity -1 $G --gap 0
expect 2 "a zero min_gap" "min_gap '0': give the smallest lubrication gap" -- force richefeu min_gap 0 $G --gap 0
expect 1 "a viscosity without min_gap" "viscosity 0.001 needs min_gap" -- force richefeu viscosity 1e-3 $G --gap 0
expect 2 "keyword without value before an option" "keyword 'gamma' needs a value" -- force richefeu gamma $G --gap 0
expect 2 "keyword without value at the end" "keyword 'theta' needs a value" -- rupture richefeu theta
expect 2 "unknown keyword without value" "unknown keyword 'bogus'" -- force richefeu bogus $G --gap 0
expect 2 "theta out of range" "theta = 95 degrees" "0 <= theta < 90" -- force richefeu theta 95 $G --gap 0
expect 2 "theta not a number" "theta '1e-3x' is not a decimal number within double range" -- force richefeu theta 1e-3x $G --gap 0
expect 2 "gamma nan" "gamma 'nan' is not a decimal number within double range" -- force richefeu gamma nan $G --gap 0
expect 2 "gamma empty" "gamma '' is not a decimal number within double range" -- force richefeu gamma "" $G --gap 0
expect 2 "gamma negative" "gamma = -0.07" "> 0" -- curve richefeu gamma -0.07 $G
expect 2 "unknown rupture rule" "rupture 'foo'" "allowed lian, willett, willett/unequal, default" -- force richefeu rupture foo $G --gap 0
expect 2 "unknown overlap rule" "overlap 'partial'" "allowed contact, none" -- force richefeu overlap partial $G --gap 0
expect 2 "unknown validity rule" "validity 'loose'" "allowed extend, strict" -- force richefeu validity loose $G --gap 0
expect 2 "c for another law" "keyword 'c'" "richefeu only" -- force willett c 0.9 $G --gap 0
expect 2 "c not positive" "c '0'" "> 0" -- force richefeu c 0 $G --gap 0
expect 2 "a law keyword after the options" "unexpected argument 'theta'" "right after the law name" -- force richefeu $G --gap 0 theta 10

# options
expect 2 "unknown option" "unknown option '--gapp'" "allowed --r1, --r2, --plane, --volume, --gap" -- force richefeu $G --gapp 0
expect 2 "unknown option with =" "unknown option '--radius'" -- force richefeu --radius=1e-3 $G --gap 0
expect 2 "option without value at the end" "option --gap needs a value" -- force richefeu $G --gap
expect 2 "option followed by an option" "option --r1 needs a value" -- force richefeu --r1 --r2 1e-3 --volume 1e-11 --gap 0
expect 2 "trailing garbage" "option --gap: '1e-3x' is not a decimal number within double range" -- force richefeu $G --gap 1e-3x
expect 2 "empty number" "option --gap: '' is not a decimal number within double range" -- force richefeu $G --gap ""
expect 2 "empty number with =" "option --gap: '' is not a decimal number within double range" -- force richefeu $G --gap=
expect 2 "nan" "option --gap: 'nan' is not a decimal number within double range" -- force richefeu $G --gap nan
expect 2 "inf" "option --volume: 'inf' is not a decimal number within double range" -- force richefeu --r1 1e-3 --r2 1e-3 --volume inf --gap 0
expect 2 "a blank before a number" "option --gap: ' 1' is not a decimal number within double range" -- force richefeu $G --gap " 1"
expect 2 "hexadecimal" "option --r1: '0x1p-10' is not a decimal number within double range" -- force richefeu --r1 0x1p-10 --r2 1e-3 --volume 1e-11 --gap 0
# one number grammar for the options and the law keywords (cb_parse_number)
expect 2 "keyword in hexadecimal" "theta '0x10' is not a decimal number within double range" -- force richefeu theta 0x10 $G --gap 0
expect 2 "keyword with a blank" "theta ' 10' is not a decimal number" -- force richefeu theta " 10" $G --gap 0
expect 2 "keyword underflow" "gamma '1e-400' is not a decimal number within double range" -- force richefeu gamma 1e-400 $G --gap 0
expect 2 "option underflow" "option --gap: '1e-400' is not a decimal number within double range" -- force richefeu $G --gap 1e-400
expect 2 "option overflow" "option --gap: '1e400' is not a decimal number within double range" -- force richefeu $G --gap 1e400
expect 2 "missing --volume" "missing option --volume" "liquid bridge volume" -- force richefeu --r1 1e-3 --r2 1e-3 --gap 0
expect 2 "missing --gap" "missing option --gap" -- force richefeu $G
for cmd in force rupture curve; do
    gap=; [ $cmd = force ] && gap="--gap 0"
    expect 2 "$cmd with neither --r2 nor --plane" "give exactly one of --r2 (sphere 2's radius) and --plane (surface 2 a plane) (none given)" -- $cmd richefeu --r1 1e-3 --volume 1e-11 $gap
    expect 2 "$cmd with --r2 and --plane" "give exactly one of --r2" "(both given)" -- $cmd richefeu $G --plane $gap
done
expect 2 "negative radius" "option --r1: -1e-3 must be > 0" -- force richefeu --r1 -1e-3 --r2 1e-3 --volume 1e-11 --gap 0
expect 2 "zero volume" "option --volume: 0 must be > 0" -- rupture richefeu --r1 1e-3 --r2 1e-3 --volume 0
expect 2 "option twice" "option --gap is given twice" -- force richefeu $G --gap 0 --gap 1e-5
expect 2 "stray argument" "unexpected argument 'extra'" -- force richefeu $G --gap 0 extra
expect 2 "--points 1" "option --points: 1 is out of range" "allowed 2 to" -- curve richefeu $G --points 1
expect 2 "--points 2.5" "option --points: '2.5' is not a whole number" -- curve richefeu $G --points 2.5
expect 2 "--points huge" "option --points: '99999999999999999999999' is not a whole number" -- curve richefeu $G --points 99999999999999999999999
expect 2 "empty range" "--from 0.0001 must be below --to 1.0000000000000001e-05" -- curve richefeu $G --from 1e-4 --to 1e-5
expect 2 "range wider than a double" "is wider than a double holds" -- curve richefeu $G --from -1e308 --to 1e308 --points 3
expect 2 "--damping 1.5" "option --damping: 1.5 must be in [0, 1]" -- pulloff richefeu $G --damping 1.5
expect 2 "--velocity 0" "option --velocity: 0 must be > 0" -- pulloff richefeu $G --velocity 0
expect 2 "--dt -1" "option --dt: -1 must be > 0" -- pulloff richefeu $G --dt -1
expect 2 "--dt far too small" "dt = 1e-300 s: the pull reaches the rupture distance" "--max-steps" -- pulloff richefeu $G --dt 1e-300
# the refusal names the quantity it checks, the default --max-steps = 10 x pull steps + 1000 +
# the steps after rupture, and its limit 1e9 (the message said 1e8 of the pull steps): a dt
# giving N = 99999990 pull steps (ceil of rupture / (v dt) = N - 0.5), the default is then
# 999999900 + 1000 + 10 = 1000000910 > 1e9
rupture=$("$CB" rupture richefeu $G | awk -F, 'NR == 2 { print $1 }')
dt_n=$(awk -v d="$rupture" 'BEGIN { printf "%.17g", d / (1e-4 * (99999990 - 0.5)) }')
expect 2 "--dt just too small" "after 99999990 steps" "the default --max-steps, 10 x 99999990 + 1000 + 10 = 1000000910, exceeds 1e9 (the most allowed)" -- pulloff richefeu $G --dt "$dt_n"
expect 2 "--dt just too small, 0 steps after" "10 x 99999990 + 1000 + 0 = 1000000900, exceeds 1e9" -- pulloff richefeu $G --dt "$dt_n" --steps-after-rupture 0
"$CB" pulloff --help >"$TMP/out"
checks=$((checks + 1))
grep -qF "which must not exceed 1e9" "$TMP/out" || fail "pulloff --help does not state the limit 1e9"
expect 2 "--steps-after-rupture -1" "option --steps-after-rupture: -1 is out of range" -- pulloff richefeu $G --steps-after-rupture -1
expect 2 "--density x" "option --density: 'x' is not a decimal number within double range" -- pulloff richefeu $G --density x
expect 2 "flag with a value" "option --rupture takes no value" -- exact $G --rupture=1

# exact
expect 2 "exact without a mode" "give exactly one of --gap, --curve, --rupture (none given)" -- exact $G
expect 2 "exact with two modes" "give exactly one of --gap, --curve, --rupture (several given)" -- exact $G --gap 0 --rupture
expect 2 "exact --theta 90" "option --theta: 90 must satisfy 0 <= angle < 90" -- exact $G --theta 90 --rupture
expect 2 "exact --curve 1" "option --curve: 1 is out of range" -- exact $G --curve 1
expect 2 "exact --steps 5" "option --steps: 5 is too few: allowed 0 (the solver's default, 256) or 16 to 1000000" -- exact $G --steps 5 --rupture
expect 2 "exact --steps 2000000" "option --steps: 2000000 is out of range" "allowed 0 to 1000000" -- exact $G --steps 2000000 --rupture
expect 2 "exact negative gap" "option --gap: -1e-6 must be >= 0" -- exact $G --gap -1e-6
expect 2 "exact takes no law" "unexpected argument 'richefeu'" -- exact richefeu $G --rupture
expect 2 "exact with --r2 and --plane" "give exactly one of --r2 (sphere 2's radius) and --plane (surface 2 a plane) (both given)" -- exact $G --plane --rupture
expect 2 "exact with neither --r2 nor --plane" "give exactly one of --r2" "(none given)" -- exact --r1 1e-3 --volume 1e-11 --rupture
expect 2 "exact --theta2 90" "option --theta2: 90 must satisfy 0 <= angle < 90" -- exact $G --theta2 90 --rupture
expect 2 "exact --plane with a value" "option --plane takes no value" -- exact --r1 1e-3 --plane=1 --volume 1e-11 --rupture

# replay
printf 'a b c d e\n1e-3 1e-3 1e-11 0 0\n' >"$TMP/table"
expect 2 "replay without --columns" "missing option --columns" -- replay richefeu --tolerance 1 "$TMP/table"
expect 2 "replay without FILE" "missing FILE" -- replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5
expect 2 "replay, two files" "unexpected argument" -- replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/table" "$TMP/table"
expect 2 "replay, unknown quantity" "unknown quantity 'vol'" "allowed r1, r2, volume, gap, distance, force" -- replay richefeu --columns r1=1,r2=2,vol=3,gap=4,force=5 "$TMP/table"
expect 2 "replay, column 0" "--columns 'r1=0'" "whole number from 1" -- replay richefeu --columns r1=0,r2=2,volume=3,gap=4,force=5 "$TMP/table"
expect 2 "replay, column x" "--columns 'r2=x'" -- replay richefeu --columns r1=1,r2=x,volume=3,gap=4,force=5 "$TMP/table"
expect 2 "replay, no =" "--columns entry 'r1'" "NAME=INDEX" -- replay richefeu --columns r1,r2=2 "$TMP/table"
expect 2 "replay, empty entry" "an empty entry" -- replay richefeu --columns r1=1,,r2=2 "$TMP/table"
expect 2 "replay, twice" "'r1' is given twice" -- replay richefeu --columns r1=1,r1=2 "$TMP/table"
expect 2 "replay, no force" "--columns lacks force=INDEX" -- replay richefeu --columns r1=1,r2=2,volume=3,gap=4 "$TMP/table"
expect 2 "replay, gap and distance" "exactly one of gap=INDEX, distance=INDEX" -- replay richefeu --columns r1=1,r2=2,volume=3,gap=4,distance=4,force=5 "$TMP/table"
expect 2 "replay, no radius" "missing r2" "--r2" -- replay richefeu --columns r1=1,volume=3,gap=4,force=5 "$TMP/table"
expect 2 "replay, column and constant" "r1 is both a column" "--r1" -- replay richefeu --r1 1e-3 --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/table"
# a column is a plain whole number: digits only, no blank, no sign ('force= 2' was taken,
# 'force=+2' refused)
for bad in " 2" "2 " "+2" "-2" "0" "02x" "0x2" "2.0" "1e1" "100001" "99999999999999999999"; do
    expect 2 "replay, column '$bad'" "--columns 'force=$bad': the column must be a whole number from 1 to 100000, in digits" -- replay richefeu --columns "r1=1,r2=2,volume=3,gap=4,force=$bad" "$TMP/table"
done
expect 2 "replay, a 100 kB --columns entry" "--columns entry 'r1xxxxxxxxxx" "...' (100002 bytes) must be NAME=INDEX" -- replay richefeu --columns "r1$LONG" "$TMP/table"
expect 2 "replay, a 100 kB column" "--columns 'r1=1111111111" "...' (100004 bytes): the column must be" -- replay richefeu --columns "r1=1$ONES" "$TMP/table"
expect 2 "replay, a 100 kB quantity" "unknown quantity 'xxxxxxxxxx" "...' (100000 bytes): allowed r1," -- replay richefeu --columns "$LONG=1" "$TMP/table"
expect 2 "replay, --tolerance -1" "option --tolerance: -1 must be >= 0" -- replay richefeu --tolerance -1 --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/table"

# help: exit 0, usage on stdout
for sub in force curve rupture exact pulloff replay; do
    for form in "$sub --help" "$sub -h" "help $sub" "$sub richefeu --help"; do
        # shellcheck disable=SC2086
        "$CB" $form >"$TMP/out" 2>"$TMP/err"
        code=$?
        checks=$((checks + 1))
        [ "$code" -eq 0 ] && grep -q "^usage: capbridge $sub" "$TMP/out" ||
            fail "'capbridge $form': exit $code, $(head -1 "$TMP/out")"
    done
done
"$CB" --help >"$TMP/out"
checks=$((checks + 1))
grep -q "^  pulloff" "$TMP/out" || fail "capbridge --help lacks the subcommand list"
"$CB" force --help >"$TMP/out"
checks=$((checks + 1))
grep -qF "$LAWS" "$TMP/out" || fail "capbridge force --help lacks the laws"
# a law's own keyword in the help as its registry row states it: the description the core's
# refusal for another law gives, the default its refusal of a bad value gives
"$CB" force willett c 0.9 $G --gap 0 >/dev/null 2>"$TMP/err"
description=$(sed -n "s/.*keyword 'c' (\(.*\)) applies to law richefeu only.*/\1/p" "$TMP/err")
"$CB" force richefeu c 0 $G --gap 0 >/dev/null 2>"$TMP/err"
default=$(sed -n 's/.*(default \(.*\))$/\1/p' "$TMP/err")
checks=$((checks + 1))
[ -n "$description" ] && [ -n "$default" ] &&
    grep -qxF "  c VALUE          $description, richefeu only (default $default)" "$TMP/out" ||
    fail "capbridge force --help lacks c as the row gives it ('$description', default '$default'): $(grep -F 'c VALUE' "$TMP/out")"


# reference: the same conventions as the other subcommands
expect 2 "reference without a set" "missing the set: allowed cases, grid" -- reference
expect 2 "reference, unknown set" "unknown set 'foo': allowed cases, grid" -- reference foo
expect 2 "reference --only without a name" "option --only needs a value" -- reference cases --only
expect 2 "reference --only twice" "option --only is given twice" -- reference cases --only W11 --only W12
expect 2 "reference, unknown name" "no configuration named 'W99' in cases" -- reference cases --only W99
"$CB" reference -h >"$TMP/out" 2>"$TMP/err"
checks=$((checks + 1))
grep -q "^usage: capbridge reference" "$TMP/out" || fail "capbridge reference -h: $(cat "$TMP/err")"

# run-time failures: exit 1 with the core's message
expect 1 "no exact bridge beyond rupture" "no bridge" -- exact $G --gap 1e-2
expect 1 "validity strict outside the validity" "validity" -- force richefeu theta 30 validity strict $G --gap 0
# a failure the inputs cause names them, so that the one out of range shows
expect 1 "force that overflows" "force at gap 0 m, law richefeu (gamma 1e+308 N/m, theta 0 deg), r1 0.001 m, r2 0.001 m, volume 1e-11 m^3" -- force richefeu gamma 1e308 $G --gap 0

finish
