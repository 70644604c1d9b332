#!/bin/sh
# runv.sh NAME BASE key=val...: write notes/embs/v/NAME.yaml and run it into notes/embs/out/NAME
set -e
name=$1; base=$2; shift 2
mkdir -p notes/embs/v
python3 notes/embs/variant.py notes/embs/$base notes/embs/v/$name.yaml "$@"
sed -i 's#\.\./\.\./scenarios#../../../scenarios#g' notes/embs/v/$name.yaml
./target/release/vbi --trust-limits --allow-large --data-dir scenarios run notes/embs/v/$name.yaml -q --force --modes-cache notes/embs/.cache --out notes/embs/out/$name
