# Shared steps of the OpenFOAM examples (examples/levitation/run.sh, examples/channel/run.sh),
# sourced by them: the OpenFOAM environment, a fresh copy of a case, timed steps with logs.
# Needs `die` defined by the caller; `step` needs $case_dir and $timings.

# The OpenFOAM environment (Debian package openfoam, v1912): an environment the user sourced
# already is kept. Checks that every tool named is on the PATH.
of_environment() {
    if ! { [ -n "${WM_PROJECT_DIR:-}" ] && command -v icoFoam >/dev/null 2>&1; }; then
        if [ -f /usr/share/openfoam/etc/bashrc ]; then
            export WM_PROJECT_DIR=/usr/share/openfoam
            # Debian's bashrc complains about missing helper scripts (bin/foamEtcFile); harmless.
            set +eu
            # shellcheck disable=SC1091
            . /usr/share/openfoam/etc/bashrc >/dev/null 2>&1
            set -eu
        fi
    fi
    local tool
    for tool in "$@"; do
        command -v "$tool" >/dev/null 2>&1 ||
            die "OpenFOAM's $tool was not found: install the Debian package openfoam (sudo apt-get install openfoam), or source your OpenFOAM's etc/bashrc first"
    done
    [ -n "${WM_PROJECT_DIR:-}" ] || die "WM_PROJECT_DIR is not set: install the Debian package openfoam, or source your OpenFOAM's etc/bashrc first"
}

# of_fresh_case SRC DEST: copies the case SRC to DEST without the leftovers of a run inside
# examples/ (time folders, mesh, VTK, postProcessing, logs).
of_fresh_case() {
    mkdir -p "$(dirname "$2")"
    rm -rf "$2"
    cp -r "$1" "$2"
    rm -rf "$2"/[1-9]* "$2"/0.[0-9]* "$2/constant/polyMesh" "$2/VTK" "$2/postProcessing" "$2"/log.*
}

# of_time_step LIMIT "CANDIDATES": the largest candidate [s] (each dividing the write interval)
# that is at most LIMIT [s] (the Courant bound); the smallest candidate if none is.
of_time_step() {
    awk -v lim="$1" -v list="$2" 'BEGIN { n = split(list, c, " ");
        for (i = 1; i <= n; i++) if (c[i] + 0 <= lim) { print c[i]; exit } print c[n] }'
}

now() { date +%s.%N; }

step() {  # step NAME COMMAND...: run in the case folder, log to log.NAME, time it
    local name=$1; shift
    local t0 t1
    t0=$(now)
    if ! (cd "$case_dir" && "$@") > "$case_dir/log.$name" 2>&1; then
        echo "run.sh: error: $name failed; the end of $case_dir/log.$name:" >&2
        tail -n 20 "$case_dir/log.$name" >&2
        exit 1
    fi
    t1=$(now)
    local s
    s=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
    echo "$name $s" >> "$timings"
    echo "  $name: $s s (log: $case_dir/log.$name)"
}
