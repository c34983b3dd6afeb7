#!/usr/bin/env python3
"""commands.py PASSLAB WORKDIR [DOC_GLOB ...]: every `passlab ...` command shown in README.md, docs/*.md and the
presets' READMEs runs after the quick start, so no documented command goes stale (a renamed
flag, a moved preset, a verb that changed).

Each command runs as shown in a sandbox: a copy of presets/, passes/ and tests/ as PASSLAB_ROOT
(so nothing in the checkout changes, not even with --update), and per document a fresh working
folder and HOME holding the fixtures its examples name (~/Downloads/XsXXDn.json, toy.json,
/autograder/submission -> $HOME/autograder/submission). So that the whole catalogue is not run
again, long verbs are bounded, and only these: `render --frames N` renders at most 4, `run` gets --frames 2 (unless it has --frames or
--seconds), `bench` --frames 2 --warmup 0, `mutate` --max 1 (its own --max too), `test` without a preset gets
presets/fundamentals/fullscreen-pass, --seconds N becomes --seconds 1; `grade P --exercise
presets/P/exercise` (an exercise as shipped) is left to cli/exercises-FAMILY, which grades every
one and checks that it fails as shipped, and `gallery` (the whole catalogue) to the gallery test.
A shell tail (`&& ...`,
`| ...`, `> file`) is left out: only passlab's part is the product's.

A command passes when it exits 0 or 1 (1: a test or grade that fails, which an exercise as
shipped does) and prints no usage error, no "no preset", no "did you mean" and no "unknown";
exit 2 (usage), 3 (environment) or a signal fail it, naming the file and line it came from."""
import glob, os, re, shlex, shutil, subprocess, sys

passlab, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Which documents: globs relative to the repository (ctest splits them over two entries).
patterns = sys.argv[3:] or ["README.md", "docs/*.md", "presets/**/README.md"]
docs = sorted({d for p in patterns for d in glob.glob(p, root_dir=repo, recursive=True)})


def commands(path):
    """(line, text) of each passlab command in a code block (indented or fenced)."""
    lines = open(os.path.join(repo, path), encoding="utf-8").read().split("\n")
    out, fenced, i = [], False, 0
    while i < len(lines):
        raw = lines[i]
        if raw.lstrip().startswith("```"):
            fenced = not fenced
            i += 1
            continue
        code = fenced or raw.startswith("    ")
        text = raw.strip()
        if text.startswith("$ "):
            text = text[2:]
        for prefix in ("xvfb-run -a ", "build/default/lab/"):
            text = text.removeprefix(prefix)
        start = i
        if code and text.startswith("passlab "):
            while text.endswith("\\") and i + 1 < len(lines):
                i += 1
                text = text[:-1] + " " + lines[i].strip()
            out.append((start + 1, text))
        i += 1
    return out


def bounded(text, home):
    text = re.split(r"\s(?:&&|\||>)\s", text)[0]
    text = re.sub(r"\s+#.*$", "", text)
    if re.search(r"<[a-z]+>|\[options\]|\bFAMILY\b|\bPRESET\b", text):
        return None  # a synopsis or a template, not a command
    args = shlex.split(text.replace("~/", home + "/").replace("/autograder/", home + "/autograder/"))[1:]
    verb = args[0] if args else ""
    has = lambda f: any(a == f or a.startswith(f + "=") for a in args)
    args = ["1" if i > 0 and args[i - 1] == "--seconds" else a for i, a in enumerate(args)]
    if verb == "render":  # a progressive reference's 256 frames would take minutes here
        args = [str(min(4, int(a))) if i > 0 and args[i - 1] == "--frames" and a.isdigit() else a for i, a in enumerate(args)]
    if verb == "run" and not has("--frames") and not has("--seconds"):
        args += ["--frames", "2"]
    if verb == "bench":
        args += ["--frames", "2", "--warmup", "0"]
    if verb == "mutate":
        args = ["1" if i > 0 and args[i - 1] == "--max" else a for i, a in enumerate(args)]
        if not has("--max"):
            args += ["--max", "1"]
    def is_presets(a):  # a preset, or a folder of them, as the argument names it
        return any(glob.glob(os.path.join(d, "**/preset.toml"), recursive=True) for d in (a, os.path.join("presets", a)) if os.path.isdir(d))
    if verb == "grade" and len(args) >= 4 and args[2] == "--exercise" and os.path.normpath(args[3]) == os.path.normpath(
            os.path.join("presets", args[1].removeprefix("presets/"), "exercise")):
        return None  # a preset's own exercise/ as shipped: cli/exercises-FAMILY grades every one
    if verb == "gallery":
        return None  # every preset's thumbnail: the gallery ctest renders exactly that
    if verb == "test" and not any(is_presets(a) for a in args[1:] if not a.startswith("-")):
        args += ["presets/fundamentals/fullscreen-pass"]
    return [passlab] + args


shutil.rmtree(work, ignore_errors=True)
root = os.path.join(work, "root")
for d in ("presets", "passes", "tests"):
    # symlinks=True: tests/bad holds links to /dev/zero and link loops, copied as links
    shutil.copytree(os.path.join(repo, d), os.path.join(root, d), symlinks=True, ignore=shutil.ignore_patterns("test-failures"))


def sandbox(n):
    """A fresh HOME and working folder per document, as a reader starts each one: the fixtures its
    examples name, presets/, passes/ and tests/ linked to the shared copy (PASSLAB_ROOT)."""
    home, cwd = os.path.join(work, f"home-{n}"), os.path.join(work, f"cwd-{n}")
    os.makedirs(os.path.join(home, "Downloads"))
    os.makedirs(os.path.join(home, "autograder/results"))
    os.makedirs(cwd)
    shutil.copy(os.path.join(repo, "tests/import/common/src.json"), os.path.join(home, "Downloads/XsXXDn.json"))
    shutil.copy(os.path.join(repo, "tests/import/common/src.json"), os.path.join(cwd, "toy.json"))
    shutil.copytree(os.path.join(repo, "presets/shading/lambert/exercise"), os.path.join(home, "autograder/submission"))
    for d in ("presets", "passes", "tests"):
        os.symlink(os.path.join(root, d), os.path.join(cwd, d))
    env = dict(os.environ, HOME=home, PASSLAB_ROOT=root)
    env.pop("CI", None)  # the examples are what a user runs locally
    return home, cwd, env


failed, ran = [], 0
bad = re.compile(r"no preset '|did you mean|unknown (flag|option|verb|subcommand)|The following argument|Run with --help", re.I)
for n, doc in enumerate(docs):
    home, cwd, env = sandbox(n)
    os.chdir(cwd)
    for line, text in commands(doc):
        cmd = bounded(text, home)
        if cmd is None:
            continue
        ran += 1
        try:
            p = subprocess.run(cmd, env=env, cwd=cwd, capture_output=True, text=True, timeout=600)
            rc, out = p.returncode, p.stdout + p.stderr
        except subprocess.TimeoutExpired:
            rc, out = "timeout", ""
        ok = rc in (0, 1) and not bad.search(out)
        print(("ok   " if ok else "FAIL ") + f"{doc}:{line}: {text}  (exit {rc})", flush=True)
        if not ok:
            failed.append(f"{doc}:{line}: {text}\n    exit {rc}: " + "\n    ".join(out.strip().split("\n")[-6:]))
print(f"{ran} documented commands run, {len(failed)} failed")
if failed:
    print("\n".join(failed), file=sys.stderr)
    sys.exit(1)
