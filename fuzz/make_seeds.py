#!/usr/bin/python3
"""Regenerate the seed corpus fuzz/corpus/ from the project's own decks
(cases/*.rad, validation/*/case*.rad, two decks of validation/type11_drop):
comment lines dropped, each /FUNCT
cut to its first 6 points, /NODE and /GRNOD to 12 lines, decks cut to
6000 bytes at a card boundary. Plus one deck split over an #include
(fuzz_deck.c: the part after the "#FILE" line is the file inc.rad).
   fuzz/make_seeds.py      (from the repository root)"""
import glob
import os

MAXB = 6000


def trim(text):
    out, card, nin = [], None, 0
    for ln in text.splitlines():
        if ln[:1] in ('#', '$'):
            continue
        if ln.startswith('/'):
            card, nin = ln.upper(), 0
            out.append(ln)
            continue
        nin += 1
        if card and card.startswith('/FUNCT') and nin > 7:
            continue
        if card and (card.startswith('/NODE') or card.startswith('/GRNOD')) and nin > 12:
            continue
        out.append(ln)
    deck = ''
    for ln in out:
        if ln.startswith('/') and len(deck) + 200 > MAXB:
            break
        deck += ln + '\n'
    if '/END' not in deck:
        deck += '/END\n'
    return deck


def main():
    os.makedirs('fuzz/corpus', exist_ok=True)
    for old in glob.glob('fuzz/corpus/*'):
        os.remove(old)
    decks = sorted(glob.glob('cases/*.rad')) + sorted(glob.glob('validation/*/case*.rad'))
    # two box pairs (TYPE11 through /LINE/SURF of closed box meshes, TYPE19
    # of two /SURF/BOX): no case*.rad holds them
    decks += ['validation/type11_drop/mesh_bars.rad', 'validation/type11_drop/flat19.rad']
    for path in decks:
        parts = path.split('/')
        name = parts[-1][:-4] if parts[0] == 'cases' else parts[1] + '_' + parts[-1][:-4]
        with open(path) as f:
            deck = trim(f.read())
        with open('fuzz/corpus/' + name + '.rad', 'w') as f:
            f.write(deck)
    # the demo split over an include: cards up to /RBODY in the main part
    with open('fuzz/corpus/demo_sphere_drop.rad') as f:
        demo = f.read()
    k = demo.index('/SURF/')
    with open('fuzz/corpus/include_split.rad', 'w') as f:
        f.write(demo[:k] + '#include inc.rad\n/END\n#FILE\n' + demo[k:])


main()
