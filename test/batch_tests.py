#!/usr/bin/env python3
# Tests of `spectralseg batch` and `batch-merge`, run by CTest as a user runs
# them (standard library only). One group per CTest test:
#   shards  - a batch of several meshes, one garbage and one empty, as 3 shards
#             plus a merge equals the unsharded run (labels, summary without
#             its timing column); same basenames in two folders; usage errors
#   jobs    - --jobs 2 (1 thread per mesh) equals --jobs 1 (2 threads)
#   resume  - a batch killed with SIGKILL halfway (deterministically: it is
#             blocked reading a named pipe) is finished by a rerun that does
#             not touch the finished meshes; stale, changed and corrupted
#             outputs are redone; --timeout stops a mesh that hangs
#   scripts - scripts/batch: the Slurm array (with a stand-in sbatch that runs
#             the tasks here), the Kubernetes job's shell (run here per index)
#             and GNU parallel (if installed) give the unsharded result
# usage: batch_tests.py GROUP SPECTRALSEG DATA WORK REPO
import csv
import json
import math
import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import time

GROUP = sys.argv[1]
TOOL, DATA, WORK, REPO = (os.path.abspath(a) for a in sys.argv[2:6])
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, flush=True)
    return condition


def run(args, expect_rc=None, env=None, **kwargs):
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, timeout=300,
                       cwd=WORK, **kwargs)
    shown = " ".join(str(a) for a in args).replace("\n", " ")
    shown = shown if len(shown) < 200 else shown[:200] + "..."
    if expect_rc is not None and not check(p.returncode == expect_rc,
                                           "%s: exit code %d, expected %d\n  stdout: %s\n  stderr: %s"
                                           % (shown, p.returncode, expect_rc, p.stdout, p.stderr)):
        return p
    print("ok: %s (exit %d)" % (shown, p.returncode), flush=True)
    return p


def batch(*args, expect_rc=None):
    return run([TOOL, "batch"] + [str(a) for a in args], expect_rc)


def torus(path, big_r, small_r, nu, nv, obj=False):
    """A closed torus of 2*nu*nv triangles, as OFF or OBJ."""
    vertices = []
    for i in range(nu):
        for j in range(nv):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            vertices.append(((big_r + small_r * math.cos(v)) * math.cos(u),
                             (big_r + small_r * math.cos(v)) * math.sin(u), small_r * math.sin(v)))
    faces = []
    for i in range(nu):
        for j in range(nv):
            a, b = i * nv + j, ((i + 1) % nu) * nv + j
            c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            faces += [(a, b, c), (a, c, d)]
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        if obj:
            f.writelines("v %.9g %.9g %.9g\n" % p for p in vertices)
            f.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in faces)
        else:
            f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
            f.writelines("%.9g %.9g %.9g\n" % p for p in vertices)
            f.writelines("3 %d %d %d\n" % t for t in faces)


def rows(folder, stem="summary"):
    with open(os.path.join(WORK, folder, stem + ".jsonl")) as f:
        return [json.loads(line) for line in f if line.strip()]


def without_timing(table):
    return [{k: v for k, v in r.items() if k != "seconds"} for r in table]


def csv_without_timing(folder):
    with open(os.path.join(WORK, folder, "summary.csv"), newline="") as f:
        table = list(csv.reader(f))
    column = table[0].index("seconds")
    return [r[:column] + r[column + 1:] for r in table]


def label_files(folder):
    out = {}
    root = os.path.join(WORK, folder)
    for base, _, files in os.walk(root):
        for name in files:
            if name.endswith(".seg"):
                with open(os.path.join(base, name), "rb") as f:
                    out[os.path.relpath(os.path.join(base, name), root)] = f.read()
    return out


def same_result(folder, reference, what):
    check(without_timing(rows(folder)) == without_timing(rows(reference)),
          "%s: summary.jsonl differs from the unsharded run's (timings left out)" % what)
    check(csv_without_timing(folder) == csv_without_timing(reference),
          "%s: summary.csv differs from the unsharded run's (timings left out)" % what)
    labels, expected = label_files(folder), label_files(reference)
    check(sorted(labels) == sorted(expected), "%s: label files %s, expected %s" % (what, sorted(labels), sorted(expected)))
    check(labels == expected, "%s: the label files differ from the unsharded run's" % what)


def make_dataset():
    """in/: 6 meshes (two named m.off in different folders, an OBJ, one in a
    subfolder of a subfolder, a garbage file and an empty file), plus a text
    file and a hidden mesh that are not taken."""
    shutil.rmtree(os.path.join(WORK, "in"), ignore_errors=True)
    shutil.copy(os.path.join(DATA, "elephant.off"), os.path.join(WORK, "x_m.off"))
    os.makedirs(os.path.join(WORK, "in", "x"))
    shutil.move(os.path.join(WORK, "x_m.off"), os.path.join(WORK, "in", "x", "m.off"))
    torus(os.path.join(WORK, "in", "y", "m.off"), 2.0, 0.5, 12, 8)
    torus(os.path.join(WORK, "in", "t.obj"), 3.0, 1.0, 10, 6, obj=True)
    torus(os.path.join(WORK, "in", "sub", "deeper", "u.off"), 2.0, 0.8, 9, 7)
    with open(os.path.join(WORK, "in", "bad.off"), "w") as f:
        f.write("this is not a mesh\n")
    open(os.path.join(WORK, "in", "empty.off"), "w").close()
    open(os.path.join(WORK, "in", "notes.txt"), "w").close()
    torus(os.path.join(WORK, "in", ".hidden.off"), 2.0, 0.5, 5, 5)


DATASET = ["bad.off", "empty.off", "sub/deeper/u.off", "t.obj", "x/m.off", "y/m.off"]
METHOD = ["--k", "3"]


def full_run():
    shutil.rmtree(os.path.join(WORK, "full"), ignore_errors=True)
    p = batch("in", "-r", "--out", "full", *METHOD, expect_rc=1)
    check("failed: 2\n" in p.stdout, "full run: stdout should count 2 failed meshes: " + p.stdout)
    return rows("full")


def test_shards():
    make_dataset()
    table = full_run()
    check([r["mesh"] for r in table] == DATASET, "meshes found: %s, expected %s" % ([r["mesh"] for r in table], DATASET))
    status = {r["mesh"]: r for r in table}
    for name in DATASET:
        ok = name not in ("bad.off", "empty.off")
        r = status.get(name, {})
        check(r.get("status") == ("ok" if ok else "error"), "%s: status %s" % (name, r.get("status")))
        if ok:
            check(r["segments"] is not None and r["segments"] >= 2 and r["faces"] > 0 and r["labels"] == name + ".seg"
                  and os.path.exists(os.path.join(WORK, "full", name + ".json")), "%s: row %s" % (name, r))
        else:
            check(r["error"] != "" and r["labels"] == "" and not os.path.exists(os.path.join(WORK, "full", name + ".seg")),
                  "%s: row %s" % (name, r))
    check("line 1" in status["bad.off"]["error"], "bad.off: error should name the line: " + status["bad.off"]["error"])
    # the two m.off have outputs of their own
    a, b = (open(os.path.join(WORK, "full", d, "m.off.seg")).read() for d in ("x", "y"))
    check(len(a.split()) == 5558 and len(b.split()) == 192, "x/m.off.seg and y/m.off.seg: one label per face each")

    shutil.rmtree(os.path.join(WORK, "sharded"), ignore_errors=True)
    shard_of = {name: i % 3 for i, name in enumerate(DATASET)}
    for s in range(3):
        fails = any(shard_of[n] == s for n in ("bad.off", "empty.off"))
        batch("in", "-r", "--out", "sharded", *METHOD, "--shard", "%d/3" % s, expect_rc=1 if fails else 0)
        mine = [r["mesh"] for r in rows("sharded", "summary-shard-%d-of-3" % s)]
        check(mine == [n for n in DATASET if shard_of[n] == s], "shard %d/3 took %s" % (s, mine))
        if s == 1:
            p = run([TOOL, "batch-merge", "sharded"], expect_rc=1)
            check("shards 2 of 3 are missing" in p.stderr, "merge with a missing shard: " + p.stderr)
            check(not os.path.exists(os.path.join(WORK, "sharded", "summary.csv")), "merge wrote a partial summary")
    p = run([TOOL, "batch-merge", "sharded"], expect_rc=1)  # 1: two meshes failed
    check("meshes: 6\nok: 4\nskipped: 0\nfailed: 2\n" in p.stdout, "merge counts: " + p.stdout)
    same_result("sharded", "full", "3 shards merged")

    # not recursive: the top folder only
    shutil.rmtree(os.path.join(WORK, "flat"), ignore_errors=True)
    batch("in", "--out", "flat", *METHOD, expect_rc=1)
    check([r["mesh"] for r in rows("flat")] == ["bad.off", "empty.off", "t.obj"], "without -r: %s" % rows("flat"))
    # a list file (names relative to the folder of the meshes) and --png, --colored-mesh
    with open(os.path.join(WORK, "list.txt"), "w") as f:
        f.write("# meshes\nin/y/m.off\n\n  in/t.obj  \nin/y/m.off\n")
    shutil.rmtree(os.path.join(WORK, "listed"), ignore_errors=True)
    batch("--list", "list.txt", "--out", "listed", *METHOD, "--png", "--colored-mesh", "ply", expect_rc=0)
    table = rows("listed")
    check([r["mesh"] for r in table] == ["t.obj", "y/m.off"], "--list: %s" % table)
    for r in table:
        check(r["png"] == r["mesh"] + ".png" and r["colored_mesh"] == r["mesh"] + ".ply" and
              os.path.getsize(os.path.join(WORK, "listed", r["png"])) > 0 and
              os.path.getsize(os.path.join(WORK, "listed", r["colored_mesh"])) > 0, "--png --colored-mesh: %s" % r)

    # usage errors (2) and inputs that do not exist (1), before any work
    for args, rc, message in [
            (["in", "--out", "u", "--k", "3", "--shard", "3/3"], 2, "--shard must be I/N"),
            (["in", "--out", "u", "--k", "3", "--shard", "1"], 2, "--shard must be I/N"),
            (["--out", "u", "--k", "3"], 2, "no mesh given"),
            (["in", "--out", "u", "--k", "0"], 2, "--k must be a positive integer"),
            (["in", "--out", "u", "--k", "3", "--jobs", "0"], 2, "--jobs"),
            (["in", "--k", "3"], 2, "--out is required"),
            (["in", "--out", "in", "--k", "3"], 2, "also an input folder"),
            (["in/t.obj", "--out", "u", "--k", "3", "--root", "in/y"], 2, "not inside the --root"),
            (["missing_folder", "--out", "u", "--k", "3"], 1, "cannot open 'missing_folder'")]:
        p = batch(*args, expect_rc=rc)
        check(message in p.stderr, "batch %s: stderr should say '%s': %s" % (" ".join(args), message, p.stderr))
    p = run([TOOL, "batch-merge", "flat"], expect_rc=1)
    check("no shard" in p.stderr, "batch-merge of an unsharded folder: " + p.stderr)


def test_jobs():
    make_dataset()
    full_run()
    shutil.rmtree(os.path.join(WORK, "jobs2"), ignore_errors=True)
    batch("in", "-r", "--out", "jobs2", *METHOD, "--jobs", "2", "--threads", "2", expect_rc=1)
    with open(os.path.join(WORK, "jobs2", "batch.json")) as f:
        check(json.load(f)["threads_per_mesh"] == 1, "--jobs 2 --threads 2: 1 thread per mesh")
    same_result("jobs2", "full", "--jobs 2")


def stamp(path):
    s = os.stat(os.path.join(WORK, path))
    return (s.st_ino, s.st_mtime_ns)


def test_resume():
    folder = os.path.join(WORK, "k")
    shutil.rmtree(folder, ignore_errors=True)
    torus(os.path.join(folder, "a.off"), 2.0, 0.5, 12, 8)
    torus(os.path.join(folder, "b.off"), 2.0, 0.7, 10, 8)
    # a large c.off: the batch spends a second or more on it, a window in which it is killed
    # halfway (the readers refuse FIFOs, which used to block it at a known point)
    torus(os.path.join(folder, "c.off"), 2.0, 0.5, 400, 150)
    torus(os.path.join(folder, "d.off"), 3.0, 0.6, 11, 7)
    out = os.path.join(WORK, "kout")
    shutil.rmtree(out, ignore_errors=True)
    args = [TOOL, "batch", "k/a.off", "k/b.off", "k/c.off", "k/d.off", "--out", "kout", "--k", "3"]
    p = subprocess.Popen(args, cwd=WORK, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    # c.off is taken up once a and b are written (--jobs 1, sorted order)
    deadline = time.time() + 60
    def b_finished():
        try:
            with open(os.path.join(out, "b.off.json")) as f:
                return "batch" in json.load(f) and os.path.exists(os.path.join(out, "b.off.seg"))
        except (OSError, ValueError):
            return False

    while time.time() < deadline and p.poll() is None and not b_finished():
        time.sleep(0.01)
    check(p.poll() is None, "the batch ended before c.off was killed halfway")
    p.send_signal(signal.SIGKILL)  # c.off is being segmented: killed halfway
    p.wait()

    def processes_of_c():
        found = []
        for pid in os.listdir("/proc"):
            try:
                with open("/proc/%s/cmdline" % pid, "rb") as f:
                    if b"k/c.off" in f.read():
                        found.append(pid)
            except OSError:
                pass
        return found

    # the process of c.off dies with the batch
    for _ in range(100):
        if not processes_of_c():
            break
        time.sleep(0.02)
    check(not processes_of_c(), "the process of c.off outlived the killed batch")
    left = sorted(f for f in os.listdir(out))
    check(left == ["a.off.json", "a.off.seg", "b.off.json", "b.off.seg"],
          "after the kill the output folder should hold a and b only (no summary, nothing of c): %s" % left)
    finished = {f: stamp(os.path.join("kout", f)) for f in left}

    os.remove(os.path.join(folder, "c.off"))
    torus(os.path.join(folder, "c.off"), 2.5, 0.5, 9, 9)
    batch(*args[2:], expect_rc=0)
    table = {r["mesh"]: r for r in rows("kout")}
    check([table[c + ".off"]["skipped"] for c in "abcd"] == [True, True, False, False],
          "rerun after the kill: skipped %s, expected a and b only" % {m: r["skipped"] for m, r in table.items()})
    check(all(r["status"] == "ok" for r in table.values()), "rerun after the kill: %s" % table)
    check(all(stamp(os.path.join("kout", f)) == s for f, s in finished.items()),
          "the outputs of a and b were written again by the rerun")
    check(table["a.off"]["seconds"] > 0, "a skipped mesh keeps the seconds of its computation")

    def skipped():
        return {r["mesh"][0]: r["skipped"] for r in rows("kout")}

    batch(*args[2:], expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", True), "a third run should skip everything: %s" % skipped())
    # a new modification time, same content: still finished (content hash)
    os.utime(os.path.join(folder, "a.off"), ns=(time.time_ns(), time.time_ns() + 5 * 10**9))
    # b changed; the JSON report of c lost its batch record (a kill between the
    # report and the record); the labels of d truncated
    torus(os.path.join(folder, "b.off"), 2.0, 0.7, 11, 8)
    with open(os.path.join(out, "c.off.json")) as f:
        report = json.load(f)
    del report["batch"]
    with open(os.path.join(out, "c.off.json"), "w") as f:
        json.dump(report, f)
    with open(os.path.join(out, "d.off.seg"), "r+") as f:
        f.truncate(10)
    batch(*args[2:], expect_rc=0)
    check(skipped() == {"a": True, "b": False, "c": False, "d": False},
          "after touching a, changing b, c's record lost, d's labels cut: %s" % skipped())
    # other options: everything again; --threads and --jobs are not options of the result
    batch(*args[2:], "--jobs", "2", "--threads", "1", expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", True), "--jobs/--threads changed: should skip everything: %s" % skipped())
    batch(*args[2:-1], "4", expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", False), "--k 4 after --k 3: should redo everything: %s" % skipped())
    check(all(r["segments"] == 4 for r in rows("kout")), "--k 4: %s" % rows("kout"))
    batch(*args[2:-1], "4", "--force", expect_rc=0)
    check(skipped() == dict.fromkeys("abcd", False), "--force: should redo everything: %s" % skipped())

    # a mesh that takes too long (240,000 faces, several seconds) is stopped by
    # --timeout and recorded; the batch goes on
    torus(os.path.join(folder, "hang.off"), 2.0, 0.5, 600, 200)
    start = time.time()
    p = batch("k/a.off", "k/hang.off", "--out", "tout", "--k", "3", "--timeout", "1", expect_rc=1)
    table = {r["mesh"]: r for r in rows("tout")}
    check(table["a.off"]["status"] == "ok" and table["hang.off"]["status"] == "error" and
          "--timeout of 1.000 s" in table["hang.off"]["error"], "--timeout: %s" % table)
    check(time.time() - start < 30, "--timeout 1 took %.1f s" % (time.time() - start))
    leftovers = [f for f in os.listdir(os.path.join(WORK, "tout")) if f.startswith("hang")]
    check(leftovers == [], "a mesh stopped by --timeout left %s" % leftovers)


def yaml_block(path, key):
    """The literal block scalar (`- |`) following `key:` in a YAML file."""
    lines = open(path).read().split("\n")
    start = next(i for i, l in enumerate(lines) if l.strip() == key + ":")
    assert lines[start + 1].strip() == "- |"
    indent = len(lines[start + 2]) - len(lines[start + 2].lstrip())
    block = []
    for l in lines[start + 2:]:
        if l.strip() and len(l) - len(l.lstrip()) < indent:
            break
        block.append(l[indent:])
    return "\n".join(block)


def test_scripts():
    make_dataset()
    full_run()
    tools = os.path.join(WORK, "bin")
    shutil.rmtree(tools, ignore_errors=True)
    os.makedirs(tools)
    env = dict(os.environ, SPECTRALSEG=TOOL, PATH=tools + os.pathsep + os.environ["PATH"])

    # Slurm: a stand-in sbatch that runs the array tasks (then the merge) here
    with open(os.path.join(tools, "sbatch"), "w") as f:
        f.write("""#!/bin/sh
array=; exports=
while [ $# -gt 0 ]; do
  case "$1" in
    --array=*) array=${1#--array=} ;;
    --export=*) exports=${1#--export=} ;;
    --*) ;;
    *) break ;;
  esac
  shift
done
script=$1; shift
n=$(cat "$0.count" 2>/dev/null || echo 100); n=$((n + 1)); echo $n > "$0.count"
if [ -n "$array" ]; then
  range=${array%%%*}; i=${range%-*}
  while [ "$i" -le "${range#*-}" ]; do
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 bash "$script" "$@" >> "$0.log" 2>&1 || echo "task $i: $?" >> "$0.log"
    i=$((i + 1))
  done
else
  for kv in $(echo "${exports#ALL}" | tr ',' ' '); do export "$kv"; done
  bash "$script" "$@" >> "$0.log" 2>&1 || echo "job: $?" >> "$0.log"
fi
echo "$n;cluster"
""")
    os.chmod(os.path.join(tools, "sbatch"), 0o755)
    shutil.rmtree(os.path.join(WORK, "slurm"), ignore_errors=True)
    p = run(["bash", os.path.join(REPO, "scripts/batch/slurm_array.sh"), "3", "slurm", "in", "-r"] + METHOD,
            expect_rc=0, env=env)
    check("array job 101 (3 shards), merge job 102" in p.stdout, "slurm_array.sh: " + p.stdout + p.stderr)
    log = open(os.path.join(tools, "sbatch.log")).read()
    check("batch-merge: 3 shards, 6 meshes" in log, "slurm: the merge job did not merge 3 shards:\n" + log)
    same_result("slurm", "full", "slurm_array.sh")

    # Kubernetes: the pod's shell, run here for each completion index
    job = os.path.join(REPO, "scripts/batch/k8s_indexed_job.yaml")
    text = open(job).read()
    shards = re.search(r'name: SHARDS\s+value: "(\d+)"', text).group(1)
    check(re.search(r"completions: (\d+)", text).group(1) == shards, "k8s: completions differs from SHARDS")
    check("completionMode: Indexed" in text, "k8s: not an Indexed Job")
    script = yaml_block(job, "args").replace("/data/results", "k8s").replace("/data/meshes", "in")
    script = script.replace("--k auto", " ".join(METHOD))
    with open(os.path.join(tools, "spectralseg"), "w") as f:
        f.write('#!/bin/sh\nexec "%s" "$@"\n' % TOOL)
    os.chmod(os.path.join(tools, "spectralseg"), 0o755)
    shutil.rmtree(os.path.join(WORK, "k8s"), ignore_errors=True)
    for i in range(int(shards)):
        run(["sh", "-c", script], expect_rc=0, env=dict(env, JOB_COMPLETION_INDEX=str(i), SHARDS=shards))
    merge = re.search(r'command: \["spectralseg", "batch-merge", "/data/results"\]',
                      open(os.path.join(REPO, "scripts/batch/k8s_merge_job.yaml")).read())
    check(merge is not None, "k8s_merge_job.yaml: not the merge command expected")
    run(["spectralseg", "batch-merge", "k8s"], expect_rc=1, env=env)
    same_result("k8s", "full", "k8s_indexed_job.yaml")
    # a pod whose batch could not run (its input is missing) fails, and is retried
    run(["sh", "-c", script.replace(" in ", " missing ")], expect_rc=1,
        env=dict(env, JOB_COMPLETION_INDEX="0", SHARDS=shards))

    # GNU parallel, if installed
    if shutil.which("parallel") is None:
        print("skipped: scripts/batch/gnu_parallel.sh (GNU parallel is not installed)")
    else:
        shutil.rmtree(os.path.join(WORK, "parallel"), ignore_errors=True)
        p = run(["bash", os.path.join(REPO, "scripts/batch/gnu_parallel.sh"), "3", "parallel", "in", "-r"] + METHOD,
                expect_rc=1, env=dict(env, PARALLEL_JOBS="2"))
        same_result("parallel", "full", "gnu_parallel.sh")


os.makedirs(WORK, exist_ok=True)
start = time.time()
{"shards": test_shards, "jobs": test_jobs, "resume": test_resume, "scripts": test_scripts}[GROUP]()
print("batch %s: %d failures, %.1f s" % (GROUP, len(failures), time.time() - start))
sys.exit(1 if failures else 0)
