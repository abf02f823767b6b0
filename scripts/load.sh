#!/usr/bin/env bash
# Load test of a running cad2mo on this machine (loopback only; bounded in count and time).
#   1. library reads: wrk, 2 threads, 64 connections, 10 s, GET /api/library/classes
#   2. 50 concurrent uploads of a ~5 MB bundle (curl), all must succeed
#   3. end-to-end conversion time of a 30-body STL bundle: upload -> job succeeded, 20 runs, p50
# Starts its own server (release build) on a free port with a fresh data folder, and stops it.
# Needs wrk (Debian: apt-get install wrk), curl and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v wrk >/dev/null || { echo "wrk is not installed (apt-get install wrk)" >&2; exit 2; }
cargo build --release -q -p cad2mo
work=$(mktemp -d)
port=$((20000 + RANDOM % 20000))
./target/release/cad2mo serve --bind "127.0.0.1:$port" --data-dir "$work/data" --workers 2 >"$work/server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$work"' EXIT
base="http://127.0.0.1:$port"
for _ in $(seq 100); do curl -fs "$base/api/health" >/dev/null && break; sleep 0.1; done

echo "== 1. library reads (wrk -t2 -c64 -d10s)"
wrk -t2 -c64 -d10s "$base/api/library/classes" | tee "$work/wrk.txt"

echo "== 2. 50 concurrent uploads of a 5 MB bundle"
python3 scripts/load/make_bundle.py "$work/big.zip" 30 5
ls -l "$work/big.zip" | awk '{print "bundle bytes:", $5}'
start=$(date +%s.%N)
seq 50 | xargs -P 50 -I{} curl -s -o "$work/up{}.json" -w "%{http_code}\n" -H "X-Requested-With: cad2mo" -F "bundle=@$work/big.zip" "$base/api/models" >"$work/codes.txt"
echo "upload statuses: $(sort "$work/codes.txt" | uniq -c | tr '\n' ' ')"
python3 - "$base" "$work" <<'PY'
import json, sys, time, urllib.request, glob
base, work = sys.argv[1], sys.argv[2]
jobs = [json.load(open(f))["job_id"] for f in glob.glob(work + "/up*.json")]
deadline = time.time() + 300
states = {}
while time.time() < deadline:
    states = {j: json.load(urllib.request.urlopen(f"{base}/api/jobs/{j}"))["status"] for j in jobs}
    if all(s in ("succeeded", "failed") for s in states.values()):
        break
    time.sleep(0.2)
counts = {s: list(states.values()).count(s) for s in set(states.values())}
print("jobs:", counts)
sys.exit(0 if counts.get("succeeded") == 50 else 1)
PY
echo "all 50 converted in $(echo "$(date +%s.%N) - $start" | bc) s"

echo "== 3. end-to-end conversion of a 30-body STL bundle (20 runs)"
python3 scripts/load/make_bundle.py "$work/small.zip" 30 0.3
python3 - "$base" "$work/small.zip" <<'PY'
import json, sys, time, urllib.request, uuid
base, path = sys.argv[1], sys.argv[2]
data = open(path, "rb").read()
times = []
for _ in range(20):
    b = uuid.uuid4().hex
    body = (f"--{b}\r\nContent-Disposition: form-data; name=\"bundle\"; filename=\"b.zip\"\r\n"
            "Content-Type: application/zip\r\n\r\n").encode() + data + f"\r\n--{b}--\r\n".encode()
    t0 = time.perf_counter()
    req = urllib.request.Request(f"{base}/api/models", data=body, headers={"Content-Type": f"multipart/form-data; boundary={b}", "X-Requested-With": "cad2mo"})
    job = json.load(urllib.request.urlopen(req))["job_id"]
    while True:
        s = json.load(urllib.request.urlopen(f"{base}/api/jobs/{job}"))["status"]
        if s in ("succeeded", "failed"):
            break
        time.sleep(0.002)
    times.append((time.perf_counter() - t0) * 1000)
    assert s == "succeeded", s
times.sort()
print(f"bundle {len(data)} bytes; p50 {times[len(times)//2]:.1f} ms, p90 {times[int(len(times)*0.9)]:.1f} ms, min {times[0]:.1f} ms")
PY
