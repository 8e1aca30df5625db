# stack.awk: the worst-case stack of each external function in the call graph GCC writes with
# -fcallgraph-info=su (GCC 10 or later; a .ci file beside each object):
#
#   awk -f stack.awk build/m4f/NAME_pm2dof.ci      (make stack does this for the M4F and M7)
#
# A function's worst stack is its frame (-fstack-usage) plus the worst stack of its callees,
# along the deepest chain. Functions GCC did not compile here (the math library, libgcc's
# floating-point routines, memset) have no frame in the graph and are not counted: add their
# frames from your C library's documentation, or measure by painting the stack (replay.c).
# Prints "bytes function", marked "(lower bound)" where a dynamic frame or recursion leaves the
# graph without a bound.
function field(line, key,   i, rest) {
    i = index(line, key ": \"")
    if (i == 0)
        return ""
    rest = substr(line, i + length(key) + 3)
    return substr(rest, 1, index(rest, "\"") - 1)
}
function worst(t, depth,   i, w, best, ub) {
    if (!(t in frame))
        return 0
    if (t in memo) {
        open_ub = open_ub || lower[t]
        return memo[t]
    }
    if (depth > 1000) {         # deeper than any chain without recursion here
        open_ub = 1
        return 0
    }
    best = 0
    ub = kind[t] == "dynamic"
    for (i = 1; i <= ncalls[t]; i++) {
        open_ub = 0
        w = worst(callee[t, i], depth + 1)
        ub = ub || open_ub
        if (w > best)
            best = w
    }
    lower[t] = ub
    open_ub = ub
    memo[t] = frame[t] + best
    return memo[t]
}
/^node: / {
    t = field($0, "title")
    l = field($0, "label")
    if (match(l, /[0-9]+ bytes \([a-z,]+\)/)) {
        split(substr(l, RSTART, RLENGTH), p, " ")
        frame[t] = p[1] + 0
        kind[t] = substr(p[3], 2, length(p[3]) - 2)
    }
}
/^edge: / {
    s = field($0, "sourcename")
    callee[s, ++ncalls[s]] = field($0, "targetname")
}
END {
    for (t in frame)
        if (index(t, ":") == 0) {          # external functions: their symbol is the title
            open_ub = 0
            w = worst(t, 0)
            printf "%7d %s%s\n", w, t, lower[t] ? " (lower bound)" : ""
        }
}
