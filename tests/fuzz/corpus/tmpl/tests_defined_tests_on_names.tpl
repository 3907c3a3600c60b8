{{ present is defined }} {{ absent is defined }} {{ absent is not defined }} {{ present is not defined }} {{ absent is undefined }}
%%context
present: 1
