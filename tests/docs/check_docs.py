#!/usr/bin/env python3
"""The docs check: every command shown in README.md and docs/*.md runs.

    check_docs.py ROOT BUILD WORK

Runs each line of every ```sh block (continuation lines joined) with bash,
and every ```pvpython block with pvbatch, from WORK: a scratch directory
holding links to ROOT's datasets/, tests/ and scripts/ and to BUILD (as
build/), and an empty out/; BUILD/bin is first on the PATH. Each must exit
0. `./scripts/test` is not run here: it is CI's own command, which runs this
check. Also: README.md is at most 300 lines, every relative link of README
and docs points at a file, and docs/settings.md is what `shadinglab
settings --markdown` prints (it is generated from the settings table).
"""
import glob
import os
import re
import shutil
import subprocess
import sys

# CI's own command (it runs this check): running it here would recurse.
NOT_RUN_HERE = {'./scripts/test'}
TIMEOUT = 600  # s; the longest documented command (scripts/demo) takes ~1 min

root, build, work = (os.path.abspath(p) for p in sys.argv[1:4])
failures = []


def check(condition, message):
    print(('ok   ' if condition else 'FAIL ') + message, flush=True)
    if not condition:
        failures.append(message)


def blocks(path):
    """(language, first line number, lines) of every fenced block."""
    out, lang, start, lines = [], None, 0, []
    for n, line in enumerate(open(path, encoding='utf-8'), 1):
        fence = re.match(r'^```(\w*)\s*$', line)
        if fence and lang is None:
            lang, start, lines = fence.group(1) or 'text', n, []
        elif line.startswith('```') and lang is not None:
            out.append((lang, start, lines))
            lang = None
        elif lang is not None:
            lines.append(line.rstrip('\n'))
    return out


def commands(lines):
    joined, current = [], ''
    for line in lines:
        if current:
            current += ' ' + line.strip()
        else:
            current = line.strip()
        if current.endswith('\\'):
            current = current[:-1].rstrip()
            continue
        if current and not current.startswith('#'):
            joined.append(current)
        current = ''
    return joined


shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, 'out'))
for name in ('datasets', 'tests', 'scripts'):
    os.symlink(os.path.join(root, name), os.path.join(work, name))
os.symlink(build, os.path.join(work, 'build'))
env = dict(os.environ)
env['PATH'] = os.path.join(build, 'bin') + os.pathsep + env.get('PATH', '')
env['SHADINGLAB_BUILD_DIR'] = build
# The Python package of the build tree, as docs/python.md says to use it.
env['PYTHONPATH'] = os.pathsep.join(
    p for p in (os.path.join(build, 'lib', 'python3', 'dist-packages'), env.get('PYTHONPATH')) if p)

docs = [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))
readme_lines = sum(1 for _ in open(docs[0], encoding='utf-8'))
check(readme_lines <= 300, 'README.md has %d lines (at most 300)' % readme_lines)

for path in docs:
    rel = os.path.relpath(path, root)
    text = open(path, encoding='utf-8').read()
    for target in re.findall(r'\]\(([^)#\s]+)(?:#[^)]*)?\)', text):
        if re.match(r'^[a-z]+://', target):
            continue
        check(os.path.exists(os.path.join(os.path.dirname(path), target)),
              '%s links to %s' % (rel, target))
    for lang, start, lines in blocks(path):
        if lang == 'sh':
            for command in commands(lines):
                where = '%s:%d: %s' % (rel, start, command)
                if command.split('#')[0].strip() in NOT_RUN_HERE:
                    print('skip %s (CI runs it; it runs this check)' % where)
                    continue
                # Scripts of the repository run from the repository itself.
                cwd = root if command.startswith('./scripts/') else work
                try:
                    r = subprocess.run(['bash', '-c', command], cwd=cwd, env=env,
                                       capture_output=True, text=True, timeout=TIMEOUT)
                    check(r.returncode == 0, '%s (exit %d) %s' % (
                        where, r.returncode, r.stderr.strip().splitlines()[-1:] if r.returncode else ''))
                except subprocess.TimeoutExpired:
                    check(False, '%s: no answer in %d s' % (where, TIMEOUT))
        elif lang == 'pvpython':
            script = os.path.join(work, 'out', 'snippet_%s_%d.py' % (os.path.basename(path), start))
            with open(script, 'w') as f:
                f.write('\n'.join(lines) + '\n')
            r = subprocess.run(['pvbatch', '--force-offscreen-rendering', script], cwd=work,
                               env=env, capture_output=True, text=True, timeout=TIMEOUT)
            check(r.returncode == 0, '%s:%d: the pvpython block runs in pvbatch (exit %d) %s' % (
                rel, start, r.returncode, r.stderr.strip().splitlines()[-3:] if r.returncode else ''))

generated = subprocess.run([os.path.join(build, 'bin', 'shadinglab'), 'settings', '--markdown'],
                           capture_output=True, text=True).stdout
check(generated == open(os.path.join(root, 'docs', 'settings.md'), encoding='utf-8').read(),
      'docs/settings.md is what `shadinglab settings --markdown` prints (regenerate it)')

print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
