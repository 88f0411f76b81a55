# Turns a vendor recording (seconds, a tab, the exact line) into a daran-sim
# session: comments dropped, the time gaps become `!advance` directives. A
# recording of several client runs restarts its clock with each run: a time
# that goes back starts a new run 1 s after the last line, as the drive kept
# running between the two (tools/replay does the same).
BEGIN { FS = "\t"; prev = 0; shift = 0 }
/^#/ { next }
NF >= 2 {
    t = $1 + shift
    if (t < prev) {
        shift = prev + 1 - $1
        t = $1 + shift
    }
    if (t > prev) {
        printf "!advance %.4f\n", t - prev
        prev = t
    }
    line = $0
    sub(/^[^\t]*\t/, "", line)
    print line
}
