// The frame stream (WebSocket) of `shadowkit serve` under hostile and rapid use: every bad
// message gets its one-line reason, an oversize one closes only its own connection, the newest
// request always gets its frame, and the server goes on serving.
//
//   node frame_stream_test.mjs SHADOWKIT_EXE
import WebSocket from 'ws';
import { startServer } from './viewer_driver.mjs';

const [exe] = process.argv.slice(2);
let failures = 0;
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures++;
}

// A connection whose answers are decoded as they come: {info, png} each.
function connect(url) {
  const socket = new WebSocket(url);
  const answers = [];
  const waiting = [];
  socket.on('message', (data, binary) => {
    if (!binary) return;
    const length = data.readUInt32LE(0);
    const info = JSON.parse(data.subarray(4, 4 + length).toString('utf8'));
    answers.push({ info, pngBytes: data.length - 4 - length });
    for (const w of waiting.splice(0)) w();
  });
  const closed = new Promise((resolve) => socket.on('close', (code) => resolve(code)));
  const opened = new Promise((resolve, reject) => {
    socket.on('open', resolve);
    socket.on('error', reject);
  });
  const until = async (done, what) => {
    const deadline = Date.now() + 120000;
    while (!done(answers)) {
      if (Date.now() > deadline) throw new Error(`no answer: ${what}`);
      await new Promise((resolve) => { waiting.push(resolve); setTimeout(resolve, 200); });
    }
  };
  return { socket, answers, closed, opened, until };
}

const frame = (id, extra = '') =>
  `{"id": ${id}, "method": "volume", "camera": {"width": 320, "height": 180}${extra}}`;

const server = await startServer(exe, 'cubes:125');
try {
  const scene = await (await fetch(`${server.url}api/scene`)).json();
  const a = connect(scene.stream);
  await a.opened;

  a.socket.send('{"id": 1, "method": ');
  await a.until((got) => got.length >= 1, 'malformed JSON');
  check(a.answers[0].info.error === 'request: is not valid JSON' && a.answers[0].pngBytes === 0,
    `malformed JSON: ${JSON.stringify(a.answers[0].info)}`);

  a.socket.send('{"id": 2, "camera": {"width": 31623, "height": 31623}}');
  await a.until((got) => got.length >= 2, 'a billion pixels');
  check(/^request: key 'camera.width'/.test(a.answers[1].info.error) && a.answers[1].info.id === null,
    `a billion pixels: ${a.answers[1].info.error}`);

  a.socket.send(Buffer.from([0, 1, 2, 3]), { binary: true });  // not a request: ignored
  a.socket.send(frame(3));
  await a.until((got) => got.some((x) => x.info.id === 3), 'a frame after garbage');
  check(a.answers.at(-1).pngBytes > 0, 'a frame after a binary message');

  const rapid = 300;
  for (let id = 100; id < 100 + rapid; id++) a.socket.send(frame(id));
  await a.until((got) => got.some((x) => x.info.id === 100 + rapid - 1), 'the newest request');
  const ids = a.answers.filter((x) => x.info.id >= 100).map((x) => x.info.id);
  check(ids.every((id, i) => i === 0 || id > ids[i - 1]), 'frames come in the order asked');
  check(ids.length < rapid,
    `${rapid} rapid requests: ${ids.length} frames, the stale ones never rendered or sent`);

  const b = connect(scene.stream);
  await b.opened;
  b.socket.send(`{"id": 1, "x": "${'a'.repeat(100 * 1024)}"}`);
  const code = await b.closed;
  check(code === 1009, `a 100 KiB message closes its own connection (${code}, "message too big")`);

  a.socket.send(frame(1000));
  const c = connect(scene.stream);
  await c.opened;
  c.socket.send(frame(1, ', "view": "difference", "light": 0'));
  await a.until((got) => got.some((x) => x.info.id === 1000), 'the first connection');
  await c.until((got) => got.length >= 1, 'a new connection');
  check(c.answers[0].info.view === 'difference', 'two connections at once are both served');
  a.socket.close();
  c.socket.close();
} finally {
  const status = await server.stop();
  check(status === 0, `the server stops on SIGTERM with status 0 (got ${status})`);
}
process.exit(failures ? 1 : 0);
