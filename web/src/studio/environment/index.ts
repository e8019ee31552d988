// The environment in the studio (issue 47): the View toolbar's Environment tools and a picked
// segment's `?E` reply, both for the String tab's context view (loaded after the first plant).
export { EnvironmentTools } from './environment-tools';
export { branchQuery, replyInWords, REPLY_REACH, type PickedQuery } from './environment-reply';
