// The few WASI (preview1) calls physics.wasm makes, for a browser: stdout and
// stderr to the console (and to onLine), the clock, an empty environment,
// and the scene files in memory as a read-only directory preopened at "/"
// (so that a game's next level, scene key game.next, opens as on disk).
// Under Node the checks use node:wasi instead (web/test/node_check.mjs).
const ERRNO = { success: 0, badf: 8, inval: 28, noent: 44, notcapable: 76 };
const FILETYPE = { chr: 2, dir: 3, file: 4 };

export class Wasi {
  // files: { "scenes/gas.json": Uint8Array, ... }; onLine(fd, text) per output line.
  constructor(files, onLine) {
    this.files = files;
    this.onLine = onLine;
    this.fds = new Map();  // fd -> { data, pos } (files), or { dir: true }
    this.next = 4;
    this.pending = { 1: '', 2: '' };
    this.memory = null;
    const f = {};
    for (const name of Object.getOwnPropertyNames(Wasi.prototype))
      if (name !== 'constructor' && !name.startsWith('_')) f[name] = Wasi.prototype[name].bind(this);
    this.imports = { wasi_snapshot_preview1: f };
  }
  _view() { return new DataView(this.memory.buffer); }
  _bytes(p, n) { return new Uint8Array(this.memory.buffer, p, n); }
  _string(p, n) { return new TextDecoder().decode(this._bytes(p, n)); }
  _isDir(path) {
    const prefix = path === '' || path === '.' ? '' : path.replace(/\/$/, '') + '/';
    return Object.keys(this.files).some((k) => k.startsWith(prefix));
  }

  environ_sizes_get(count, size) { this._view().setUint32(count, 0, true); this._view().setUint32(size, 0, true); return 0; }
  environ_get() { return 0; }
  clock_time_get(id, precision, out) {
    const ns = BigInt(Math.round((id === 0 ? Date.now() : performance.now()) * 1e6));
    this._view().setBigUint64(out, ns, true);
    return 0;
  }
  proc_exit(code) { throw new Error(`physics.wasm exited with code ${code}`); }

  fd_write(fd, iovs, count, written) {
    const v = this._view();
    let n = 0, text = '';
    for (let i = 0; i < count; i++) {
      const p = v.getUint32(iovs + 8 * i, true), len = v.getUint32(iovs + 8 * i + 4, true);
      text += this._string(p, len);
      n += len;
    }
    if (fd !== 1 && fd !== 2) return ERRNO.badf;
    const lines = (this.pending[fd] + text).split('\n');
    this.pending[fd] = lines.pop();
    for (const line of lines) this.onLine(fd, line);
    v.setUint32(written, n, true);
    return 0;
  }
  fd_read(fd, iovs, count, read) {
    const file = this.fds.get(fd);
    if (!file || file.dir) return ERRNO.badf;
    const v = this._view();
    let n = 0;
    for (let i = 0; i < count; i++) {
      const p = v.getUint32(iovs + 8 * i, true), len = v.getUint32(iovs + 8 * i + 4, true);
      const chunk = file.data.subarray(file.pos, file.pos + len);
      this._bytes(p, chunk.length).set(chunk);
      file.pos += chunk.length;
      n += chunk.length;
    }
    v.setUint32(read, n, true);
    return 0;
  }
  fd_seek(fd, offset, whence, out) {
    const file = this.fds.get(fd);
    if (!file || file.dir) return ERRNO.badf;
    const base = whence === 0 ? 0 : whence === 1 ? file.pos : file.data.length;
    const pos = base + Number(offset);
    if (pos < 0) return ERRNO.inval;
    file.pos = pos;
    this._view().setBigUint64(out, BigInt(pos), true);
    return 0;
  }
  fd_close(fd) { return this.fds.delete(fd) ? 0 : ERRNO.badf; }
  fd_fdstat_get(fd, out) {
    const v = this._view();
    const type = fd <= 2 ? FILETYPE.chr : fd === 3 || this.fds.get(fd)?.dir ? FILETYPE.dir : this.fds.has(fd) ? FILETYPE.file : 0;
    if (!type) return ERRNO.badf;
    v.setUint8(out, type);
    v.setUint16(out + 2, 0, true);
    v.setBigUint64(out + 8, 0xffffffffffffffffn, true);
    v.setBigUint64(out + 16, 0xffffffffffffffffn, true);
    return 0;
  }
  fd_fdstat_set_flags() { return 0; }
  fd_prestat_get(fd, out) {
    if (fd !== 3) return ERRNO.badf;
    this._view().setUint8(out, 0);
    this._view().setUint32(out + 4, 1, true);
    return 0;
  }
  fd_prestat_dir_name(fd, p, len) {
    if (fd !== 3 || len < 1) return ERRNO.badf;
    this._bytes(p, 1)[0] = '/'.charCodeAt(0);
    return 0;
  }
  path_open(dirfd, dirflags, p, len, oflags, rightsBase, rightsInheriting, fdflags, out) {
    const path = this._string(p, len).replace(/^\.\//, '');
    if (oflags & 1) return ERRNO.notcapable;  // O_CREAT: read only
    const fd = this.next++;
    if (this.files[path]) this.fds.set(fd, { data: this.files[path], pos: 0 });
    else if (this._isDir(path)) this.fds.set(fd, { dir: true });
    else return ERRNO.noent;
    this._view().setUint32(out, fd, true);
    return 0;
  }
  path_filestat_get(fd, flags, p, len, out) {
    const path = this._string(p, len).replace(/^\.\//, '');
    const data = this.files[path];
    if (!data && !this._isDir(path)) return ERRNO.noent;
    const v = this._view();
    for (let i = 0; i < 64; i += 8) v.setBigUint64(out + i, 0n, true);
    v.setUint8(out + 16, data ? FILETYPE.file : FILETYPE.dir);
    v.setBigUint64(out + 24, 1n, true);
    v.setBigUint64(out + 32, BigInt(data ? data.length : 0), true);
    return 0;
  }
}
