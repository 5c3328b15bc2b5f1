#!/usr/bin/env python3
"""Runs every command of the CLI over every file of a bad-input corpus and
checks the promise: exit status 2, exactly one line on stderr, no crash or
hang, the input file unchanged. Prints one line per failure and a summary;
exit status 1 when anything failed.

    python3 tests/badinput/run_corpus.py SHADINGLAB CORPUS_DIR WORK_DIR [SHADINGLAB_GUI]

With SHADINGLAB_GUI, the explorer too (without a display it reads INPUT
first, so a bad file must give its one-line error, not the display's).
"""
import hashlib
import os
import signal
import subprocess
import sys

cli, corpus, work = sys.argv[1:4]
gui = sys.argv[4] if len(sys.argv) > 4 else None
os.makedirs(work, exist_ok=True)
commands = [
    ['render', '{in}', '--backend', 'cpu', '--size', '64x48', '--out', '{work}/r.png'],
    ['compare', '{in}', '--backend', 'cpu', '--size', '48x36', '--out', '{work}/c.png'],
    ['normals', '{in}', '--out', '{work}/n.vtp'],
    ['render', '{in}', '--backend', 'cpu', '--mode', 'auto', '--max-error', '1', '--size',
     '64x48', '--out', '{work}/a.png'],
]
# Every corpus file as the optical data of --nk too (a valid mesh drawn).
mesh = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'datasets',
                    'icosphere_1.vtp')
commands += [
    ['brdf', '--spectral', '--nk', '{in}', '--term', 'F', '--theta-l', '0'],
    ['render', mesh, '--backend', 'cpu', '--model', 'cook-torrance', '--spectral', '--nk', '{in}',
     '--size', '32x24', '--out', '{work}/s.png'],
]
programs = [(cli, command) for command in commands]
if gui:
    programs.append((gui, ['--scene', 'modes', '{in}', '--screenshot', '{work}/g.png']))
TIMEOUT = 60  # seconds; none of these inputs needs more than a second
counts = {'ok': 0, 'crash': 0, 'hang': 0, 'exit': 0, 'lines': 0, 'modified': 0}
env = {k: v for k, v in os.environ.items() if k != 'DISPLAY'}


def digest(path):
    with open(path, 'rb') as f:
        return hashlib.sha256(f.read()).hexdigest()


for name in sorted(os.listdir(corpus)):
    path = os.path.join(corpus, name)
    before = digest(path)
    for program, command in programs:
        args = [program] + [a.format(**{'in': path, 'work': work}) for a in command]
        label = '%s %s %s' % (os.path.basename(program), command[0], name)
        try:
            run = subprocess.run(args, capture_output=True, timeout=TIMEOUT, env=env)
        except subprocess.TimeoutExpired:
            counts['hang'] += 1
            print('HANG    ' + label)
            continue
        err = run.stderr.decode('utf-8', 'replace').strip('\n')
        if run.returncode < 0 or run.returncode >= 128:
            counts['crash'] += 1
            sig = -run.returncode if run.returncode < 0 else run.returncode - 128
            print('CRASH   %s (signal %d): %s' % (label, sig, err.splitlines()[-1:] if err else ''))
        elif run.returncode != 2:
            counts['exit'] += 1
            print('EXIT %d  %s: %s' % (run.returncode, label, err[:200]))
        elif len(err.splitlines()) != 1:
            counts['lines'] += 1
            print('LINES   %s: %d lines on stderr' % (label, len(err.splitlines())))
        else:
            counts['ok'] += 1
        if digest(path) != before:
            counts['modified'] += 1
            print('MODIFIED ' + label)
print('runs: %d ok, %d crashes, %d hangs, %d wrong exit status, %d not one line, %d inputs modified'
      % (counts['ok'], counts['crash'], counts['hang'], counts['exit'], counts['lines'], counts['modified']))
sys.exit(0 if counts['ok'] == sum(v for k, v in counts.items() if k != 'modified') and not counts['modified'] else 1)
