#!/usr/bin/python3
"""Mutation fuzzing of `solve --input`: thousands of random edits of valid JSON lines (characters
deleted, inserted or replaced, values swapped for extreme or malformed ones, keys renamed) in one
batch. solve must answer every line (a result or an error naming the line), exit 0 or 3, never
crash and never report an internal error. Seeded; usage: fuzz_jsonl.py MOMENTBENCH SEED_FILE WORKDIR."""
import json
import os
import random
import subprocess
import sys

mb, seed_file, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
valid = [line for line in open(seed_file) if line.strip()]
tokens = ['1e308', '-1e308', 'NaN', 'Infinity', '-0', '0', '1e-320', '99999999999999999999', '[', ']', '{', '}',
          ':', ',', '"', 'null', 'true', '[]', '{}', '"z^"', '"1/(z-0.5)"', '"log(z)"', '[1e308, 1e308]',
          '"power4"', '"trig4"', '2.5', '-5', '4000000000', '"grid"', '"technique"', '"hamburger4"']
rng = random.Random(20261203)
lines = []
for _ in range(3000):
    s = rng.choice(valid).rstrip('\n')
    for _ in range(rng.randint(1, 3)):
        at = rng.randrange(len(s)) if s else 0
        how = rng.randrange(6)
        if how == 0:
            s = s[:at] + s[at + rng.randint(1, 4):]
        elif how == 1:
            s = s[:at] + chr(rng.randint(32, 126)) + s[at:]
        elif how == 2:
            s = s[:at] + rng.choice(tokens) + s[at:]
        elif how == 3:  # a whole value replaced
            try:
                q = json.loads(s)
                if isinstance(q, dict) and q:
                    key = rng.choice(list(q))
                    q[key] = json.loads(rng.choice([t for t in tokens if t not in '[]{}:,"'] + ['"x"']))
                    s = json.dumps(q)
            except (ValueError, TypeError):
                pass
        elif how == 4:  # a key renamed
            s = s.replace('"zf"', '"fz"', 1) if rng.random() < 0.5 else s.replace('"grid"', '"gird"', 1)
        else:  # a number replaced
            digits = [i for i, c in enumerate(s) if c.isdigit()]
            if digits:
                i = rng.choice(digits)
                s = s[:i] + rng.choice(tokens) + s[i + 1:]
    if s.strip():
        lines.append(s.replace('\n', ' '))
batch = os.path.join(work, 'fuzz.jsonl')
with open(batch, 'w') as f:
    f.write('\n'.join(lines) + '\n')
run = subprocess.run([mb, 'solve', '--input', batch, '--output', os.path.join(work, 'out.jsonl')],
                     capture_output=True, text=True, timeout=600)
if run.returncode not in (0, 3):
    sys.exit(f'fuzz_jsonl: exit {run.returncode} (crash or abort)\n{run.stderr[-2000:]}')
if 'internal error' in run.stderr:
    sys.exit('fuzz_jsonl: internal error\n' + '\n'.join(l for l in run.stderr.splitlines() if 'internal error' in l)[:2000])
answers = open(os.path.join(work, 'out.jsonl')).read().splitlines()
if len(answers) != len(lines):
    sys.exit(f'fuzz_jsonl: {len(lines)} lines in, {len(answers)} answers out')
statuses = {}
for a in answers:
    status = json.loads(a).get('status')
    statuses[status] = statuses.get(status, 0) + 1
print(f'fuzz_jsonl: {len(lines)} mutated lines, answers by status: {statuses}')
