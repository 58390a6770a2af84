"""bullet_sim.batch on a two-node Ray cluster on the loopback address, against the same
episodes in this process. Run by test_ray_batch.py with an interpreter that has Ray
(build/learning_venv/bin/python); exits 0 when every check passes.

Both nodes are `ray start --block` processes in sessions of their own, with a temporary
directory of their own and every port chosen free, so that they never meet another Ray on
the machine; teardown kills the two sessions and any process left whose command line names
the temporary directory (never `ray stop`, which stops every Ray of the machine).
"""

import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

import numpy as np

SEEDS = [11, 12, 13, 14]
# a fixed action sequence (ROBOTIS's 5 yaw rates): straight on, then turning both ways
ACTIONS = [2, 2, 2, 1, 1, 2, 3, 3, 2, 0, 2, 4, 2, 2, 1, 3, 2, 2, 0, 4] * 2
START_TIMEOUT = 60.0


def free_ports(n):
    socks = [socket.socket() for _ in range(n)]
    for s in socks:
        s.bind(('127.0.0.1', 0))
    ports = [s.getsockname()[1] for s in socks]
    for s in socks:
        s.close()
    return ports


def ray_start(ray_bin, temp_dir, head_port, head, log):
    ports = free_ports(7)
    cmd = [ray_bin, 'start', '--block', '--num-cpus=1', '--node-ip-address=127.0.0.1',
           f'--temp-dir={temp_dir}', '--disable-usage-stats',
           f'--node-manager-port={ports[0]}', f'--object-manager-port={ports[1]}',
           f'--dashboard-agent-listen-port={ports[2]}', f'--dashboard-agent-grpc-port={ports[3]}',
           f'--metrics-export-port={ports[4]}', f'--runtime-env-agent-port={ports[5]}']
    if head:
        cmd += ['--head', f'--port={head_port}', '--include-dashboard=false',
                f'--ray-client-server-port={ports[6]}']
    else:
        cmd += [f'--address=127.0.0.1:{head_port}']
    return subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)


def teardown(procs, temp_dir):
    for p in procs:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        p.wait(timeout=10)
    try:  # daemons that left the sessions: only those of this temporary directory
        import psutil
        for proc in psutil.process_iter(['pid', 'cmdline']):
            if any(temp_dir in arg for arg in (proc.info['cmdline'] or [])):
                try:
                    proc.kill()
                except psutil.Error:
                    pass
    except ImportError:
        pass
    shutil.rmtree(temp_dir, ignore_errors=True)


def wait_nodes(ray, n):
    deadline = time.monotonic() + START_TIMEOUT
    while time.monotonic() < deadline:
        alive = [nd for nd in ray.nodes() if nd['Alive']]
        if len(alive) >= n:
            return alive
        time.sleep(0.5)
    raise AssertionError(f'{n} Ray nodes not alive after {START_TIMEOUT} s: {ray.nodes()}')


def main():
    # token authentication with a token of this cluster's own (Ray's default would read or
    # write ~/.ray/auth_token), in the environment of both nodes and of this driver
    os.environ['RAY_AUTH_MODE'] = 'token'
    os.environ['RAY_AUTH_TOKEN'] = secrets.token_hex(32)
    import ray
    from bullet_sim import batch

    ray_bin = os.path.join(os.path.dirname(sys.executable), 'ray')
    temp_dir = tempfile.mkdtemp(prefix='bsray', dir='/tmp')  # short: Ray's socket paths
    head_port = free_ports(1)[0]
    procs = []
    log = open(os.path.join(temp_dir, 'ray_start.log'), 'w')
    try:
        procs.append(ray_start(ray_bin, temp_dir, head_port, True, log))
        # the head must be up before the worker node joins it
        deadline = time.monotonic() + START_TIMEOUT
        while True:
            with socket.socket() as s:
                if s.connect_ex(('127.0.0.1', head_port)) == 0:
                    break
            if procs[0].poll() is not None or time.monotonic() > deadline:
                raise AssertionError('the Ray head did not start: '
                                     + open(log.name).read()[-3000:])
            time.sleep(0.3)
        procs.append(ray_start(ray_bin, temp_dir, head_port, False, log))
        ray.init(address=f'127.0.0.1:{head_port}', log_to_driver=False,
                 runtime_env={'env_vars': batch.worker_env_vars()})
        alive = wait_nodes(ray, 2)
        assert len(alive) == 2, alive
        node_ids = {nd['NodeID'] for nd in alive}

        t0 = time.monotonic()
        remote = batch.run(SEEDS, actions=ACTIONS, workers=2)
        t_ray = time.monotonic() - t0
        ray.shutdown()
        local = batch.run(SEEDS, actions=ACTIONS, use_ray=False)

        assert [r['seed'] for r in remote] == SEEDS
        for r, l in zip(remote, local):
            assert r['length'] == l['length'] and r['length'] > 0, (r, l)
            # to the bit: the same floats, not merely close ones
            assert r['return'] == l['return'], (r['seed'], r['return'], l['return'])
            assert r['final_obs'].dtype == l['final_obs'].dtype == np.float32
            assert r['final_obs'].tobytes() == l['final_obs'].tobytes(), r['seed']
            assert (r['success'], r['terminated'], r['truncated']) == \
                (l['success'], l['terminated'], l['truncated'])
            assert l['node_id'] is None
        ran_on = {r['node_id'] for r in remote}
        assert ran_on == node_ids, f'episodes ran on {ran_on}, the nodes are {node_ids}'
        # the episodes differ from seed to seed (start and goal are drawn from it)
        assert len({r['return'] for r in remote}) == len(SEEDS)
        print(f'ok: {len(SEEDS)} episodes on 2 nodes in {t_ray:.1f} s, returns '
              + ' '.join(f'{r["return"]:.3f}' for r in remote)
              + ', lengths ' + ' '.join(str(r['length']) for r in remote))
    finally:
        try:
            ray.shutdown()
        except Exception:  # noqa: BLE001
            pass
        log.close()
        teardown(procs, temp_dir)


if __name__ == '__main__':
    main()
