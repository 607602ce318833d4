// The CPU time of Chromium's GPU process (Node side, Linux): with SwiftShader every draw runs on
// the CPU in that process, so the run time of its threads is what a frame costs, and unlike wall
// time (timer queries included) it does not grow while other programs hold the cores. On this
// 2-core machine, shared with other test runs, timer queries of one setting spread by ±25 % between
// identical runs at a load of 10, this clock by about ±7 % (measured on the bench's head frames).
// Read from /proc/<pid>/task/*/schedstat (nanoseconds on the CPU, per thread).
import { readdirSync, readFileSync } from 'node:fs';

const parentOf = (pid) => {
  const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
  return stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1];
};

/** Whether `pid` is `ancestor` or descends from it (within a few generations: zygotes sit between). */
function descendsFrom(pid, ancestor) {
  for (let p = pid, i = 0; i < 6 && p && p !== '0'; i++, p = parentOf(p)) if (p === ancestor) return true;
  return false;
}

/**
 * The clock of `browser`'s GPU process, or null where there is none to read (not Linux, no /proc).
 * @param {import('puppeteer-core').Browser} browser
 * @returns {{ pid: string, nowMs(): number } | null} nowMs: CPU time of all its threads so far, ms
 */
export function gpuProcessClock(browser) {
  const browserPid = String(browser.process()?.pid ?? '');
  let pids;
  try {
    pids = readdirSync('/proc').filter((p) => /^\d+$/.test(p));
  } catch {
    return null;
  }
  const pid = pids.find((p) => {
    try {
      return readFileSync(`/proc/${p}/cmdline`, 'utf8').includes('--type=gpu-process') && descendsFrom(p, browserPid);
    } catch {
      return false; // a process that ended meanwhile
    }
  });
  if (!pid) return null;
  return {
    pid,
    nowMs() {
      let ns = 0;
      for (const task of readdirSync(`/proc/${pid}/task`)) {
        try {
          ns += Number(readFileSync(`/proc/${pid}/task/${task}/schedstat`, 'utf8').split(' ')[0]);
        } catch {
          // a thread that ended meanwhile (SwiftShader's workers last as long as the process)
        }
      }
      return ns / 1e6;
    },
  };
}
