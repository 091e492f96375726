// Shared by check_mcap.mjs and check_viewer.mjs: a gdnav MCAP file opened with the official TypeScript reader.
import { open } from "node:fs/promises";
import { McapIndexedReader } from "@mcap/core";
import zstd from "@foxglove/wasm-zstd";

// zstd chunks through @foxglove/wasm-zstd (loaded before the first use).
export async function decompressHandlers() {
  await zstd.isLoaded;
  return { zstd: (buffer, size) => zstd.decompress(buffer, Number(size)) };
}

// A random-access IReadable over a file (its close() closes the file).
export async function fileReadable(file) {
  const handle = await open(file, "r");
  const size = BigInt((await handle.stat()).size);
  return {
    close: () => handle.close(),
    size: async () => size,
    read: async (offset, length) => {
      const buf = new Uint8Array(Number(length));
      const { bytesRead } = await handle.read(buf, 0, buf.length, Number(offset));
      if (bytesRead !== buf.length) throw new Error(`short read at ${offset}`);
      return buf;
    },
  };
}

// The indexed reader of `file` (summary, statistics, chunk indexes, metadata, attachments) and closeFile().
export async function indexedReader(file) {
  const readable = await fileReadable(file);
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers: await decompressHandlers() });
  return { reader, closeFile: readable.close };
}

// A list of at most 50 mismatches and the function that adds one.
export function problemList() {
  const problems = [];
  return [problems, (s) => { if (problems.length < 50) problems.push(s); }];
}
