# Turns a vendor recording (seconds, a tab, the exact line) into a daran-sim
# session: comments dropped, the time gaps become `!advance` directives.
BEGIN { FS = "\t"; prev = 0 }
/^#/ { next }
NF >= 2 {
    t = $1 + 0
    if (t > prev) {
        printf "!advance %.4f\n", t - prev
        prev = t
    }
    line = $0
    sub(/^[^\t]*\t/, "", line)
    print line
}
