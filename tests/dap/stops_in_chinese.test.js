// Under a Chinese locale the debugger's alarm and block budget stops read as `cncmacro run
// --locale zh-CN` prints them (one function for both). `cncmacro dap` driven through a real DAP client.
'use strict';

const assert = require('node:assert/strict');
const { describe, test } = require('node:test');
const { clientPerTest, program } = require('./client.js');

const dc = clientPerTest();

describe('stops in the client language', () => {
  test('an alarm stop reads 报警 112：除数为零 in a Chinese locale', async () => {
    const { event } = await dc.begin({ program: program('divide_by_zero.nc') }, { locale: 'zh-CN' });
    assert.equal(event.body.reason, 'exception');
    assert.equal(event.body.description, '报警 112：除数为零');
    const info = await dc.exceptionInfoRequest({ threadId: 1 });
    assert.equal(info.body.description, '报警 112：除数为零');
  });

  test('an alarm stop reads ALARM 112: division by zero in English', async () => {
    const { event } = await dc.begin({ program: program('divide_by_zero.nc') });
    assert.equal(event.body.description, 'ALARM 112: division by zero');
  });

  test('the block budget stop is in Chinese in a Chinese locale', async () => {
    const { event } = await dc.begin({ program: program('endless.nc'), maxBlocks: 1000 }, { locale: 'zh-CN' });
    assert.equal(event.body.reason, 'exception');
    assert.equal(event.body.description, '执行 1000 个程序段后停止：已达到程序段数上限（是否有死循环？）');
  });
});
